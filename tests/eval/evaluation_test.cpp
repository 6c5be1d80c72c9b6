// SPDX-License-Identifier: MIT
// Integration: a synthetic dataset with exact ground truth, a small trained archive, and the
// evaluation end to end. The bookkeeping is asserted, against oracles whose answers are known
// exactly; accuracy is asserted in evaluation_accuracy_test.cpp, on frames at template poses
// (this dataset's random views are mostly outside its coarse archive's envelope).
#include "eval/evaluation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "eval/bop_targets.h"
#include "eval/eval_report.h"
#include "eval_fixtures.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

constexpr int kImages = 4;

class EvaluationTest : public test::TinyEvalSuite<kImages> {
 protected:
  static EvalPlan Plan(const FrameSelectionOptions& selection = {}) {
    return PlanEvaluation(data_->dataset, {1}, selection, true);
  }
};

// Returns every annotated instance at its true pose, moved by `offset_mm` along the camera's x.
EvalMethod Oracle(double offset_mm) {
  return {"oracle", [offset_mm](const BopFrame& frame) {
            std::vector<Detection> detections;
            for (const BopGroundTruth& gt : frame.gt) {
              Detection detection;
              detection.obj_id = gt.obj_id;
              detection.cam_from_model = gt.cam_from_model;
              detection.cam_from_model.t.x() += offset_mm;
              detections.push_back(detection);
            }
            return detections;
          }};
}

TEST_F(EvaluationTest, PlanSelectsEveryImageOfTheTarget) {
  const EvalPlan plan = Plan();
  ASSERT_EQ(plan.frames.size(), static_cast<std::size_t>(kImages));
  for (const EvalFrame& frame : plan.frames) {
    ASSERT_EQ(frame.targets.size(), 1u);
    EXPECT_EQ(frame.targets[0].obj_id, 1);
    EXPECT_EQ(frame.targets[0].gt_indices, std::vector<int>{0});
  }
  ASSERT_EQ(plan.dataset.models.count(1), 1u);
  EXPECT_FALSE(plan.dataset.models.at(1).symmetric);
  EXPECT_GT(plan.dataset.models.at(1).points.size(), 8u);
}

TEST_F(EvaluationTest, PerfectPosesScoreExactlyHundredPercent) {
  const EvalPlan plan = Plan();
  const auto runs = RunMethods(plan.dataset, plan.frames, {Oracle(0.0)}, {});
  const MethodSummary summary = Summarize(runs[0], plan.dataset.models);
  ASSERT_EQ(summary.objects.size(), 1u);
  EXPECT_EQ(summary.objects[0].frames, kImages);
  EXPECT_EQ(summary.objects[0].AccuracyPercent(), 100.0);
  EXPECT_EQ(summary.objects[0].Proj2DPercent(), 100.0);
  EXPECT_EQ(summary.objects[0].DetectionRatePercent(), 100.0);
  for (const TargetOutcome& outcome : runs[0].outcomes) {
    EXPECT_EQ(outcome.pose.error_mm, 0.0);
    EXPECT_EQ(outcome.pose.box_iou, 1.0);
  }
}

TEST_F(EvaluationTest, PosesOffByAFifthOfTheDiameterScoreZero) {
  const EvalPlan plan = Plan();
  const double diameter = plan.dataset.models.at(1).diameter_mm;
  const auto runs = RunMethods(plan.dataset, plan.frames, {Oracle(0.2 * diameter)}, {});
  const MethodSummary summary = Summarize(runs[0], plan.dataset.models);
  EXPECT_EQ(summary.overall.detected, kImages);
  EXPECT_EQ(summary.overall.correct, 0);
  for (const TargetOutcome& outcome : runs[0].outcomes) {
    EXPECT_NEAR(outcome.pose.error_mm, 0.2 * diameter, 1e-6);  // a translation moves all points
  }
  // The same offset passes with km = 0.25.
  EvalMetricOptions lenient;
  lenient.km = 0.25;
  const auto lenient_runs =
      RunMethods(plan.dataset, plan.frames, {Oracle(0.2 * diameter)}, lenient);
  EXPECT_EQ(Summarize(lenient_runs[0], plan.dataset.models).overall.correct, kImages);
}

TEST_F(EvaluationTest, DetectorRunReportIsConsistent) {
  const Detector detector({data_->archive});
  DetectorOptions options;
  const Evaluation evaluation = Evaluate(detector, options, data_->dataset, {}, {});
  const MethodSummary& summary = evaluation.summary;
  EXPECT_EQ(summary.name, "scene-patch");
  EXPECT_EQ(summary.frames, kImages);
  ASSERT_EQ(evaluation.run.outcomes.size(), static_cast<std::size_t>(kImages));
  ASSERT_EQ(summary.objects.size(), 1u);
  const ObjectSummary& object = summary.objects[0];
  EXPECT_EQ(object.frames, kImages);
  EXPECT_LE(object.correct, object.detected);
  EXPECT_LE(object.box_correct, object.detected);
  EXPECT_LE(object.detected, object.frames);
  // The summary counts a right pose only when its detection is accepted (confidence at least the
  // run's threshold).
  int correct = 0;
  for (const TargetOutcome& outcome : evaluation.run.outcomes) {
    if (!outcome.detected) continue;
    EXPECT_TRUE(std::isfinite(outcome.pose.error_mm));
    EXPECT_EQ(outcome.pose.correct, outcome.pose.error_mm <= 0.1 * object.diameter_mm);
    const bool accepted = outcome.confidence >= summary.min_confidence;
    correct += outcome.pose.correct && accepted ? 1 : 0;
  }
  EXPECT_EQ(object.correct, correct);
  EXPECT_DOUBLE_EQ(object.AccuracyPercent(), 100.0 * correct / kImages);
  EXPECT_GT(summary.median_frame_ms, 0.0);

  EvalRunInfo info;
  info.dataset_dir = data_->dataset.string();
  test::TempDir out;
  WriteEvalReport(out.path(), info, summary, evaluation.run);
  const auto json = nlohmann::json::parse(ReadFileBytes(out / "report.json"));
  EXPECT_EQ(json["summary"]["frames"], kImages);
  EXPECT_EQ(json["summary"]["objects"][0]["correct"], correct);
  EXPECT_EQ(json["outcomes"].size(), static_cast<std::size_t>(kImages));
}

TEST_F(EvaluationTest, TargetsFileAndFrameLimitSelectFrames) {
  FrameSelectionOptions selection;
  selection.targets = LoadBopTargets(data_->dataset / "test_targets_bop19.json");
  EXPECT_EQ(Plan(selection).frames.size(), static_cast<std::size_t>(kImages));
  selection.max_frames = 2;
  EXPECT_EQ(Plan(selection).frames.size(), 2u);
}

TEST_F(EvaluationTest, BadInputIsRefusedWithTheFileNamed) {
  FrameSelectionOptions selection;
  selection.scene_id = 2;
  EXPECT_THROW(Plan(selection), Error);
  try {
    PlanEvaluation(dir_->path() / "nowhere", {1}, {}, true);
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_THAT(error.what(), HasSubstr("nowhere"));
  }
  EXPECT_THROW(PlanEvaluation(data_->dataset, {1, 5}, {}, true), FormatError);  // no model 5
}

TEST_F(EvaluationTest, DepthModesRefuseScenesWithoutDepth) {
  test::TempDir copy;
  fs::copy(data_->dataset, copy.path(), fs::copy_options::recursive);
  fs::remove_all(copy / "test" / "000001" / "depth");
  try {
    PlanEvaluation(copy.path(), {1}, {}, true);
    FAIL() << "no exception";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("000001"));
    EXPECT_THAT(error.what(), HasSubstr("no depth"));
  }
  EXPECT_EQ(PlanEvaluation(copy.path(), {1}, {}, false).frames.size(),
            static_cast<std::size_t>(kImages));
}

}  // namespace
}  // namespace layermod
