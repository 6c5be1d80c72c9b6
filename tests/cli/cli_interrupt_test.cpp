// SPDX-License-Identifier: MIT
// Ctrl-C during `layermod train` leaves no archive (and keeps a previous one intact).
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>

#include "cli/cli_runner.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace layermod::test {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> LongTraining(const fs::path& out) {
  // Tens of thousands of templates: far longer than the time to send a signal.
  return SplitArgs("train --model " + (SourceDir() / "resources/sample/bracket.ply").string() +
                   " --camera " + (SourceDir() / "resources/sample/camera.json").string() +
                   " --dmin 400 --dmax 3000 --azimuth 0:5:355 --elevation 0:5:90 --roll "
                   "-45:5:45 --threads 1 --out " +
                   out.string());
}

int CountEntries(const fs::path& dir) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++count;
  return count;
}

TEST(CliInterruptTest, SigintDuringTrainingWritesNothing) {
  TempDir dir;
  CliProcess process(LongTraining(dir / "x.layermod"));
  ASSERT_TRUE(process.WaitForOutput("training "));
  process.Signal(SIGINT);
  const CliResult result = process.Wait();
  EXPECT_EQ(result.exit_code, 130) << result.output;
  EXPECT_NE(result.output.find("cancelled"), std::string::npos) << result.output;
  EXPECT_EQ(CountEntries(dir.path()), 0);
}

TEST(CliInterruptTest, SigintKeepsThePreviousArchive) {
  TempDir dir;
  WriteFileAtomically(dir / "x.layermod", "previous complete archive");
  CliProcess process(LongTraining(dir / "x.layermod"));
  ASSERT_TRUE(process.WaitForOutput("training "));
  process.Signal(SIGINT);
  EXPECT_EQ(process.Wait().exit_code, 130);
  EXPECT_EQ(ReadFileBytes(dir / "x.layermod"), "previous complete archive");
  EXPECT_EQ(CountEntries(dir.path()), 1);
}

}  // namespace
}  // namespace layermod::test
