// SPDX-License-Identifier: MIT
// `layermod eval` end to end: the report it writes, the table it prints, and its refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "eval_fixtures.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr int kImages = 3;

class EvalCliTest : public test::TinyEvalSuite<kImages> {
 protected:
  static std::vector<std::string> EvalArgs(const fs::path& out) {
    return {
        "eval",  "--archive", data_->archive_file.string(), "--dataset", data_->dataset.string(),
        "--out", out.string()};
  }
};

TEST_F(EvalCliTest, WritesTheReportAndPrintsTheTable) {
  test::TempDir out;
  std::vector<std::string> args = EvalArgs(out / "report");
  args.insert(args.end(), {"--targets", (data_->dataset / "test_targets_bop19.json").string(),
                           "--mode", "exhaustive", "--km", "0.15"});
  const test::CliResult result = test::RunCli(args);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("| 1 | ADD | 3 |"));
  const auto json = nlohmann::json::parse(ReadFileBytes(out / "report" / "report.json"));
  EXPECT_EQ(json["setup"]["mode"], "exhaustive");
  EXPECT_EQ(json["setup"]["km"], 0.15);
  EXPECT_EQ(json["summary"]["frames"], kImages);
  EXPECT_EQ(json["summary"]["objects"][0]["frames"], kImages);
  const int correct = json["summary"]["objects"][0]["correct"];
  const int detected = json["summary"]["objects"][0]["detected"];
  EXPECT_LE(correct, detected);
  EXPECT_DOUBLE_EQ(json["summary"]["objects"][0]["accuracy_percent"].get<double>(),
                   100.0 * correct / kImages);
  EXPECT_THAT(ReadFileBytes(out / "report" / "report.md"), HasSubstr("| 1 | ADD | 3 |"));
}

TEST_F(EvalCliTest, RefusesBadInputWithoutWritingAReport) {
  test::TempDir out;
  std::vector<std::string> missing = EvalArgs(out / "r1");
  missing[4] = (dir_->path() / "nowhere").string();
  test::CliResult result = test::RunCli(missing);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.output, HasSubstr("nowhere"));

  WriteFileAtomically(out / "bad.json", "[{\"im_id\": ");
  std::vector<std::string> bad_targets = EvalArgs(out / "r2");
  bad_targets.insert(bad_targets.end(), {"--targets", (out / "bad.json").string()});
  result = test::RunCli(bad_targets);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.output, HasSubstr("bad.json"));

  std::vector<std::string> no_scene = EvalArgs(out / "r3");
  no_scene.insert(no_scene.end(), {"--scene", "7"});
  result = test::RunCli(no_scene);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.output, HasSubstr("no scene 7"));

  std::vector<std::string> bad_mode = EvalArgs(out / "r4");
  bad_mode.insert(bad_mode.end(), {"--mode", "psychic"});
  EXPECT_EQ(test::RunCli(bad_mode).exit_code, 2);

  for (const char* name : {"r1", "r2", "r3", "r4"}) EXPECT_FALSE(fs::exists(out / name)) << name;
}

TEST_F(EvalCliTest, BenchWritesOneEntryPerMethod) {
  test::TempDir out;
  const test::CliResult result =
      test::RunCli({"bench", "--archive", data_->archive_file.string(), "--dataset",
                    data_->dataset.string(), "--frames", "2", "--out", (out / "b.json").string()});
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_THAT(result.output, HasSubstr("| cv::linemod | 2 |"));
  const auto json = nlohmann::json::parse(ReadFileBytes(out / "b.json"));
  ASSERT_EQ(json["methods"].size(), 3u);
  EXPECT_EQ(json["methods"][0]["method"], "scene-patch");
  EXPECT_EQ(json["methods"][0]["frames"], 2);
  EXPECT_EQ(json["setup"]["max_frames"], 2);
  EXPECT_EQ(json["setup"]["suite"], "depth");
}

TEST_F(EvalCliTest, BenchRefusesADatasetWithoutDepth) {
  test::TempDir copy;
  fs::copy(data_->dataset, copy.path(), fs::copy_options::recursive);
  fs::remove_all(copy / "test" / "000001" / "depth");
  const test::CliResult result =
      test::RunCli({"bench", "--archive", data_->archive_file.string(), "--dataset",
                    copy.path().string(), "--out", (copy / "b.json").string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_THAT(result.output, HasSubstr("no depth images"));
  EXPECT_FALSE(fs::exists(copy / "b.json"));
}

}  // namespace
}  // namespace layermod
