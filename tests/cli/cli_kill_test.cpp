// SPDX-License-Identifier: MIT
// Kills `layermod train` (SIGKILL and SIGINT) at random moments, from start-up to past the end of
// the run, and checks that the target path always holds a complete archive (the previous one or
// the newly finished one), never a partial file.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <random>
#include <string>
#include <thread>

#include "cli/cli_runner.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace layermod::test {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::vector<std::string> Training(const fs::path& out) {
  // About a second of work on one thread: long enough to be hit anywhere, short enough to repeat.
  return SplitArgs("train --model " + (SourceDir() / "resources/sample/bracket.ply").string() +
                   " --camera " + (SourceDir() / "resources/sample/camera.json").string() +
                   " --dmin 600 --dmax 900 --azimuth 0:20:340 --elevation 15:15:75 --roll "
                   "-20:20:20 --threads 1 --out " +
                   out.string());
}

// Removes temporary files a SIGKILLed writer could not clean up; returns how many there were.
int RemoveLeftoverTemporaries(const fs::path& dir, const fs::path& target) {
  int leftovers = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path() == target) continue;
    EXPECT_NE(entry.path().string().find(".tmp."), std::string::npos)
        << "unexpected file " << entry.path();
    fs::remove(entry.path());
    ++leftovers;
  }
  return leftovers;
}

TEST(CliKillTest, TargetHoldsACompleteArchiveWheneverTrainingIsKilled) {
  TempDir dir;
  const fs::path target = dir / "part.layermod";
  const auto start = Clock::now();
  const CliResult first = RunCli(Training(target));
  const auto run_time = Clock::now() - start;
  ASSERT_EQ(first.exit_code, 0) << first.output;
  std::string previous = ReadFileBytes(target);

  std::mt19937 rng(2026);
  std::uniform_int_distribution<long> delay_us(
      0, std::chrono::duration_cast<std::chrono::microseconds>(run_time).count() * 11 / 10);
  int kept_previous = 0;
  int replaced = 0;
  int leftovers = 0;
  for (int round = 0; round < 16; ++round) {
    const int signal_number = round % 2 == 0 ? SIGKILL : SIGINT;
    CliProcess process(Training(target));
    std::this_thread::sleep_for(std::chrono::microseconds(delay_us(rng)));
    process.Signal(signal_number);
    const CliResult killed = process.Wait();
    ASSERT_TRUE(fs::exists(target)) << "round " << round << ": the archive disappeared";
    const std::string now = ReadFileBytes(target);
    if (now == previous) {
      ++kept_previous;
    } else {
      // The run finished before the signal: the new archive must be complete and readable.
      const CliResult inspected = RunCli({"inspect", target.string()});
      ASSERT_EQ(inspected.exit_code, 0) << "round " << round << ": partial archive\n"
                                        << inspected.output << killed.output;
      ++replaced;
      previous = now;
    }
    leftovers += RemoveLeftoverTemporaries(dir.path(), target);
  }
  RecordProperty("kept_previous", kept_previous);
  RecordProperty("replaced_by_complete_run", replaced);
  RecordProperty("temporaries_left_by_sigkill", leftovers);
  EXPECT_GT(kept_previous, 0);  // the delays must actually interrupt runs
}

TEST(CliKillTest, KilledFirstTrainingLeavesNoArchive) {
  TempDir dir;
  const fs::path target = dir / "part.layermod";
  for (const int signal_number : {SIGKILL, SIGINT}) {
    CliProcess process(Training(target));
    ASSERT_TRUE(process.WaitForOutput("training "));
    process.Signal(signal_number);
    process.Wait();
    EXPECT_FALSE(fs::exists(target));
    RemoveLeftoverTemporaries(dir.path(), target);
  }
}

}  // namespace
}  // namespace layermod::test
