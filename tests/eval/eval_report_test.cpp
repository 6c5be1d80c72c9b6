// SPDX-License-Identifier: MIT
#include "eval/eval_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

using ::testing::HasSubstr;

TargetOutcome Outcome(int image_id) {
  TargetOutcome outcome;
  outcome.scene_id = 1;
  outcome.image_id = image_id;
  outcome.obj_id = 3;
  return outcome;
}

MethodRun SampleRun() {
  MethodRun run;
  run.name = "exhaustive";
  TargetOutcome hit = Outcome(4);
  hit.detected = true;
  hit.score = 91.5f;
  hit.pose.error_mm = 2.5;
  hit.pose.proj2d_px = std::numeric_limits<double>::infinity();
  hit.pose.correct = true;
  hit.frame_time_ms = 12.0;
  TargetOutcome miss = Outcome(5);
  miss.frame_time_ms = 14.0;
  run.outcomes = {hit, miss};
  run.frame_times_ms = {12.0, 14.0};
  return run;
}

MethodSummary Summary(const MethodRun& run) {
  std::map<std::int32_t, EvalModel> models;
  models.emplace(3, EvalModel(3, 100.0, false, {Eigen::Vector3d::Zero()}));
  return Summarize(run, models);
}

EvalRunInfo Info() {
  EvalRunInfo info;
  info.dataset_dir = "/data/synth";
  info.archives = {"a.layermod"};
  info.detector.mode = DetectionMode::kExhaustive;
  info.scene_id = 1;
  return info;
}

TEST(EvalReportTest, JsonHoldsSetupSummaryAndOutcomes) {
  const MethodRun run = SampleRun();
  const nlohmann::json json = EvalReportJson(Info(), Summary(run), run);
  EXPECT_EQ(json["setup"]["dataset"], "/data/synth");
  EXPECT_EQ(json["setup"]["scene_id"], 1);
  EXPECT_EQ(json["setup"]["km"], 0.1);
  EXPECT_EQ(json["summary"]["method"], "exhaustive");
  EXPECT_EQ(json["summary"]["objects"][0]["frames"], 2);
  EXPECT_EQ(json["summary"]["objects"][0]["accuracy_percent"], 50.0);
  EXPECT_EQ(json["summary"]["overall"]["correct"], 1);
  EXPECT_EQ(json["summary"]["frame_time_ms"]["median"], 13.0);
  ASSERT_EQ(json["outcomes"].size(), 2u);
  EXPECT_TRUE(json["outcomes"][0]["proj2d_px"].is_null());  // infinity is not JSON
  EXPECT_EQ(json["outcomes"][0]["error_mm"], 2.5);
  EXPECT_FALSE(json["outcomes"][1].contains("error_mm"));
}

TEST(EvalReportTest, TableHasARowPerObjectAndAll) {
  const std::string table = SummaryTable(Summary(SampleRun()));
  EXPECT_THAT(table, HasSubstr("| 3 | ADD | 2 | 50.0 | 0.0 | 0.0 | 13.0 | 13.0 |"));
  EXPECT_THAT(table, HasSubstr("| all |  | 2 | 50.0 |"));
  EXPECT_THAT(EvalReportMarkdown(Info(), Summary(SampleRun()), SampleRun()),
              HasSubstr("(scene 1)"));
}

TEST(EvalReportTest, MissesAreNamedByCause) {
  const MethodRun run = SampleRun();  // one right, one not detected
  const MethodSummary summary = Summary(run);
  EXPECT_EQ(MissesText(summary),
            "Targets missed: 1 of 2: 0 outside the envelope, 1 not detected, 0 with a wrong pose "
            "(0 of them accepted), 0 with a right pose below the confidence threshold.\n");
  EXPECT_THAT(MissesTable(summary), HasSubstr("| 3 | 2 | 1 | 0 | 1 | 0 (0) | 0 |"));
  EXPECT_THAT(EvalReportMarkdown(Info(), summary, run), HasSubstr("Targets missed: 1 of 2"));
  EXPECT_EQ(EvalReportJson(Info(), summary, run)["summary"]["overall"]["misses"]["undetected"], 1);
  MethodRun all_right = run;
  all_right.outcomes.pop_back();
  EXPECT_EQ(MissesText(Summary(all_right)), "");
}

// Targets outside the envelope are named with the first one's reason, and those found all the
// same (ICP can turn a near template's pose onto them) are counted apart.
TEST(EvalReportTest, TargetsOutsideTheEnvelopeAreCountedWithThoseFound) {
  MethodRun run = SampleRun();  // image 4 right, image 5 not detected
  for (TargetOutcome& outcome : run.outcomes) {
    outcome.outside_envelope = true;
    outcome.envelope_note = "roll -99 deg outside the trained -45..45 deg";
  }
  const MethodSummary summary = Summary(run);
  EXPECT_EQ(EnvelopeCoverageText(summary, run),
            "obj 3: 2 of 2 targets outside the archive's envelope, farther than a sampling step "
            "from every template, 1 of them found all the same (first: scene 1 image 4, roll -99 "
            "deg outside the trained -45..45 deg)\n");
  EXPECT_EQ(EnvelopeCoverageText(Summary(SampleRun()), SampleRun()), "");
}

TEST(EvalReportTest, WritesBothFilesIntoANewFolder) {
  test::TempDir dir;
  const MethodRun run = SampleRun();
  CheckReportFolder(dir / "out");
  WriteEvalReport(dir / "out", Info(), Summary(run), run);
  const nlohmann::json json = nlohmann::json::parse(ReadFileBytes(dir / "out" / "report.json"));
  EXPECT_EQ(json["summary"]["frames"], 2);
  EXPECT_THAT(ReadFileBytes(dir / "out" / "report.md"), HasSubstr("| Object |"));
  EXPECT_THAT(ReadFileBytes(dir / "out" / "report.md"), HasSubstr("precision-recall curve"));
  EXPECT_TRUE(json["summary"]["precision_recall"].contains("area"));
  const std::string plot = ReadFileBytes(dir / "out" / "pr_curve.png");
  ASSERT_GT(plot.size(), 8u);
  EXPECT_EQ(plot.substr(1, 3), "PNG");
}

TEST(EvalReportTest, RefusesAFolderThatCannotBeMade) {
  test::TempDir dir;
  EXPECT_THROW(CheckReportFolder(dir / "no" / "such" / "out"), IoError);
}

}  // namespace
}  // namespace layermod
