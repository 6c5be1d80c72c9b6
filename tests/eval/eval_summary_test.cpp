// SPDX-License-Identifier: MIT
#include "eval/eval_summary.h"

#include <gtest/gtest.h>

namespace layermod {
namespace {

TargetOutcome Outcome(std::int32_t obj_id, bool detected, bool correct, bool proj2d, bool box,
                      double time_ms) {
  TargetOutcome outcome;
  outcome.obj_id = obj_id;
  outcome.detected = detected;
  outcome.pose.correct = correct;
  outcome.pose.proj2d_correct = proj2d;
  outcome.pose.box_correct = box;
  outcome.frame_time_ms = time_ms;
  return outcome;
}

std::map<std::int32_t, EvalModel> Models() {
  std::map<std::int32_t, EvalModel> models;
  models.emplace(1, EvalModel(1, 80.0, false, {Eigen::Vector3d::Zero()}));
  models.emplace(2, EvalModel(2, 120.0, true, {Eigen::Vector3d::Zero()}));
  return models;
}

TEST(EvalSummaryTest, Quantiles) {
  EXPECT_EQ(Quantile({}, 0.5), 0.0);
  EXPECT_EQ(Quantile({7.0}, 0.9), 7.0);
  EXPECT_DOUBLE_EQ(Quantile({4.0, 1.0, 3.0, 2.0}, 0.5), 2.5);
  // 10 values 1..10: rank 0.9 * 9 = 8.1 -> 9.1.
  EXPECT_DOUBLE_EQ(Quantile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0.9), 9.1);
}

TEST(EvalSummaryTest, CountsPerObjectAndOverall) {
  MethodRun run;
  run.name = "scene-patch";
  // Object 1: 4 frames, 3 detected, 2 correct, 3 in 2D, 3 boxes. Object 2: 1 frame, correct.
  run.outcomes = {Outcome(1, true, true, true, true, 10), Outcome(1, true, true, true, true, 20),
                  Outcome(1, true, false, true, true, 30),
                  Outcome(1, false, false, false, false, 40),
                  Outcome(2, true, true, false, true, 40)};
  run.frame_times_ms = {10, 20, 30, 40};  // object 2 shares the last frame with object 1
  const MethodSummary summary = Summarize(run, Models());
  EXPECT_EQ(summary.name, "scene-patch");
  ASSERT_EQ(summary.objects.size(), 2u);
  const ObjectSummary& first = summary.objects[0];
  EXPECT_EQ(first.obj_id, 1);
  EXPECT_EQ(first.frames, 4);
  EXPECT_EQ(first.detected, 3);
  EXPECT_DOUBLE_EQ(first.AccuracyPercent(), 50.0);
  EXPECT_DOUBLE_EQ(first.Proj2DPercent(), 75.0);
  EXPECT_DOUBLE_EQ(first.DetectionRatePercent(), 75.0);
  EXPECT_DOUBLE_EQ(first.mean_time_ms, 25.0);
  EXPECT_DOUBLE_EQ(first.median_time_ms, 25.0);
  EXPECT_DOUBLE_EQ(first.diameter_mm, 80.0);
  EXPECT_TRUE(summary.objects[1].symmetric_metric);
  EXPECT_DOUBLE_EQ(summary.objects[1].AccuracyPercent(), 100.0);
  EXPECT_EQ(summary.overall.frames, 5);
  EXPECT_DOUBLE_EQ(summary.overall.AccuracyPercent(), 60.0);
  EXPECT_DOUBLE_EQ(summary.mean_object_accuracy_percent, 75.0);
  EXPECT_EQ(summary.frames, 4);
  EXPECT_DOUBLE_EQ(summary.mean_frame_ms, 25.0);
  EXPECT_DOUBLE_EQ(summary.p90_frame_ms, 37.0);
}

TEST(EvalSummaryTest, ConfidenceThresholdAndAbsentObjects) {
  MethodRun run;
  TargetOutcome right = Outcome(1, true, true, true, true, 10);
  right.confidence = 0.9;
  TargetOutcome doubtful_right = Outcome(1, true, true, true, true, 10);
  doubtful_right.confidence = 0.3;
  TargetOutcome wrong = Outcome(1, true, false, false, false, 10);
  wrong.confidence = 0.6;
  TargetOutcome on_absent = Outcome(2, true, false, false, false, 10);
  on_absent.present = false;
  on_absent.confidence = 0.7;
  TargetOutcome quiet_absent = Outcome(2, false, false, false, false, 10);
  quiet_absent.present = false;
  run.outcomes = {right, doubtful_right, wrong, on_absent, quiet_absent};
  const MethodSummary all = Summarize(run, Models(), 0.0);
  EXPECT_EQ(all.overall.frames, 3);  // absent pairs are not targets
  EXPECT_EQ(all.overall.detected, 3);
  EXPECT_EQ(all.overall.correct, 2);
  EXPECT_EQ(all.overall.absent, 2);
  EXPECT_EQ(all.overall.absent_detected, 1);
  EXPECT_DOUBLE_EQ(all.overall.PrecisionPercent(), 50.0);  // 2 right of 4 accepted
  EXPECT_DOUBLE_EQ(all.overall.AbsentDetectedPercent(), 50.0);
  // Object 2 is only ever absent: it has no accuracy and does not pull the mean down.
  EXPECT_DOUBLE_EQ(all.mean_object_accuracy_percent, all.objects[0].AccuracyPercent());

  const MethodSummary strict = Summarize(run, Models(), 0.8);
  EXPECT_DOUBLE_EQ(strict.min_confidence, 0.8);
  EXPECT_EQ(strict.overall.detected, 1);
  EXPECT_EQ(strict.overall.correct, 1);
  EXPECT_EQ(strict.overall.absent_detected, 0);
  EXPECT_DOUBLE_EQ(strict.overall.PrecisionPercent(), 100.0);
}

TEST(EvalSummaryTest, EveryMissHasOneCause) {
  MethodRun run;
  TargetOutcome right = Outcome(1, true, true, true, true, 10);
  right.confidence = 0.9;
  TargetOutcome right_but_doubtful = Outcome(1, true, true, true, true, 10);
  right_but_doubtful.confidence = 0.5;
  TargetOutcome confident_wrong = Outcome(1, true, false, false, false, 10);
  confident_wrong.confidence = 0.95;
  TargetOutcome doubtful_wrong = Outcome(1, true, false, false, false, 10);
  doubtful_wrong.confidence = 0.2;
  const TargetOutcome undetected = Outcome(1, false, false, false, false, 10);
  TargetOutcome outside = Outcome(2, true, false, false, false, 10);
  outside.outside_envelope = true;
  TargetOutcome outside_but_found = Outcome(2, true, true, true, true, 10);
  outside_but_found.outside_envelope = true;
  outside_but_found.confidence = 0.9;
  TargetOutcome absent = Outcome(2, true, false, false, false, 10);
  absent.present = false;
  absent.confidence = 0.9;
  run.outcomes = {right,   right_but_doubtful, confident_wrong, doubtful_wrong, undetected,
                  outside, outside_but_found,  absent};
  const MethodSummary summary = Summarize(run, Models(), 0.8);
  const ObjectSummary& all = summary.overall;
  EXPECT_EQ(all.frames, 7);
  EXPECT_EQ(all.correct, 2);
  EXPECT_EQ(all.missed_outside_envelope, 1);  // the one found anyway is not a miss
  EXPECT_EQ(all.missed_undetected, 1);
  EXPECT_EQ(all.missed_wrong_pose, 2);
  EXPECT_EQ(all.wrong_pose_accepted, 1);
  EXPECT_EQ(all.missed_below_threshold, 1);
  EXPECT_EQ(all.missed_outside_envelope + all.missed_undetected + all.missed_wrong_pose +
                all.missed_below_threshold,
            all.frames - all.correct);
  EXPECT_EQ(summary.objects[0].missed_wrong_pose, 2);
  EXPECT_EQ(summary.objects[1].missed_outside_envelope, 1);
}

TEST(EvalSummaryTest, AnEmptyRunHasZeroRates) {
  const MethodSummary summary = Summarize(MethodRun{}, Models());
  EXPECT_TRUE(summary.objects.empty());
  EXPECT_EQ(summary.overall.AccuracyPercent(), 0.0);
  EXPECT_EQ(summary.median_frame_ms, 0.0);
}

}  // namespace
}  // namespace layermod
