// SPDX-License-Identifier: MIT
#include "util/log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace layermod {
namespace {

TEST(LogTest, SinkReceivesMessagesAndCanBeRestored) {
  std::vector<std::string> seen;
  LogSink previous = SetLogSink([&](LogLevel level, std::string_view message) {
    seen.push_back(std::string(LogLevelName(level)) + ":" + std::string(message));
  });
  LogWarning("origin far from centre");
  LogInfo("done");
  SetLogSink(previous);
  LogInfo("not captured");
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0], "warning:origin far from centre");
  EXPECT_EQ(seen[1], "info:done");
}

}  // namespace
}  // namespace layermod
