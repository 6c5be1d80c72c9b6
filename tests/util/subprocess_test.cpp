// SPDX-License-Identifier: MIT
#include "util/subprocess.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace layermod {
namespace {
using namespace std::chrono_literals;

TEST(SubprocessTest, CollectsOutputErrorAndExitCode) {
  const ProcessResult result =
      RunProcess({"/bin/sh", "-c", "printf 'a\\000b'; echo oops >&2; exit 3"}, 10s);
  EXPECT_EQ(result.out, std::string("a\0b", 3));
  EXPECT_EQ(result.err, "oops\n");
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_EQ(result.signal_number, 0);
  EXPECT_FALSE(result.timed_out);
}

TEST(SubprocessTest, ReadsOutputLargerThanAPipeBuffer) {
  const ProcessResult result = RunProcess({"/bin/sh", "-c", "head -c 3000000 /dev/zero"}, 30s);
  EXPECT_EQ(result.out.size(), 3000000u);
  EXPECT_EQ(result.exit_code, 0);
}

TEST(SubprocessTest, ReportsTheSignalThatEndedTheProcess) {
  const ProcessResult result = RunProcess({"/bin/sh", "-c", "kill -SEGV $$"}, 10s);
  EXPECT_EQ(result.signal_number, 11);
}

TEST(SubprocessTest, KillsAProcessThatOutlivesTheTimeout) {
  const ProcessResult result = RunProcess({"/bin/sleep", "60"}, 1s);
  EXPECT_TRUE(result.timed_out);
  EXPECT_EQ(result.signal_number, 9);
}

TEST(SubprocessTest, AMissingProgramIsAnError) {
  EXPECT_THROW(RunProcess({"/no/such/program"}, 1s), Error);
  EXPECT_THROW(RunProcess({}, 1s), Error);
}

}  // namespace
}  // namespace layermod
