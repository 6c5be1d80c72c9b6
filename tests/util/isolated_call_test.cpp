// SPDX-License-Identifier: MIT
#include "util/isolated_call.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <thread>

#include "util/error.h"

namespace layermod {
namespace {
using ::testing::HasSubstr;
using namespace std::chrono_literals;

template <typename E, typename F>
std::string ThrownMessage(F&& call) {
  try {
    call();
  } catch (const E& error) {
    return error.what();
  }
  return "(nothing thrown)";
}

TEST(IsolatedCallTest, ReturnsTheChildsBytesIncludingZeros) {
  const std::string bytes("a\0b\xff", 4);
  EXPECT_EQ(RunIsolated([&] { return bytes; }, 10s, "reader"), bytes);
  const std::string large(3 << 20, 'x');  // larger than a pipe buffer
  EXPECT_EQ(RunIsolated([&] { return large; }, 10s, "reader"), large);
}

TEST(IsolatedCallTest, RunsInAnotherProcess) {
  const pid_t parent = ::getpid();
  const std::string child = RunIsolated([] { return std::to_string(::getpid()); }, 10s, "reader");
  EXPECT_NE(child, std::to_string(parent));
}

TEST(IsolatedCallTest, ErrorsComeBackWithTheirTypeAndMessage) {
  EXPECT_EQ(ThrownMessage<FormatError>([] {
              RunIsolated([]() -> std::string { throw FormatError("'x.ply': bad"); }, 10s, "r");
            }),
            "'x.ply': bad");
  EXPECT_EQ(ThrownMessage<IoError>([] {
              RunIsolated([]() -> std::string { throw IoError("'x.ply': gone"); }, 10s, "r");
            }),
            "'x.ply': gone");
  EXPECT_THAT(ThrownMessage<FormatError>(
                  [] { RunIsolated([]() -> std::string { throw std::bad_alloc(); }, 10s, "r"); }),
              HasSubstr("out of memory"));
}

TEST(IsolatedCallTest, ACrashIsAFormatErrorNotTheEndOfTheCaller) {
  const std::string message = ThrownMessage<FormatError>([] {
    RunIsolated(
        []() -> std::string {
          std::raise(SIGSEGV);
          return "";
        },
        10s, "'part.off': the mesh importer");
  });
  EXPECT_THAT(message, HasSubstr("'part.off': the mesh importer crashed (signal 11)"));
}

TEST(IsolatedCallTest, AHangIsStoppedAtTheTimeout) {
  const std::string message = ThrownMessage<FormatError>([] {
    RunIsolated(
        []() -> std::string {
          std::this_thread::sleep_for(60s);
          return "";
        },
        1s, "'part.ply': the mesh importer");
  });
  EXPECT_THAT(message, HasSubstr("took longer than 1 s"));
}

}  // namespace
}  // namespace layermod
