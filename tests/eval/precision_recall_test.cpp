// SPDX-License-Identifier: MIT
#include "eval/precision_recall.h"

#include <gtest/gtest.h>

namespace layermod {
namespace {

TargetOutcome Outcome(bool present, bool detected, double confidence, bool correct) {
  TargetOutcome outcome;
  outcome.present = present;
  outcome.detected = detected;
  outcome.confidence = confidence;
  outcome.pose.correct = correct;
  return outcome;
}

// Four targets: right at 0.9 and 0.7, wrong at 0.8, one missed; a detection of an absent
// object at 0.6 and an absent object nobody detected.
std::vector<TargetOutcome> Outcomes() {
  return {Outcome(true, true, 0.9, true),   Outcome(true, true, 0.8, false),
          Outcome(true, true, 0.7, true),   Outcome(true, false, 0.0, false),
          Outcome(false, true, 0.6, false), Outcome(false, false, 0.0, false)};
}

TEST(PrecisionRecallTest, OnePointPerConfidenceBestFirst) {
  const PrecisionRecallCurve curve = ComputePrecisionRecall(Outcomes());
  EXPECT_EQ(curve.targets, 4);
  ASSERT_EQ(curve.points.size(), 4u);
  EXPECT_DOUBLE_EQ(curve.points[0].threshold, 0.9);
  EXPECT_DOUBLE_EQ(curve.points[0].precision, 1.0);
  EXPECT_DOUBLE_EQ(curve.points[0].recall, 0.25);
  EXPECT_DOUBLE_EQ(curve.points[1].precision, 0.5);  // the wrong pose at 0.8
  EXPECT_DOUBLE_EQ(curve.points[2].precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(curve.points[2].recall, 0.5);
  EXPECT_DOUBLE_EQ(curve.points[3].precision, 0.5);  // the absent object's detection
  EXPECT_DOUBLE_EQ(curve.points[3].recall, 0.5);
}

TEST(PrecisionRecallTest, AreaUsesTheBestPrecisionAtOrBeyondEachRecall) {
  // Recall 0..0.25 at precision 1, 0.25..0.5 at the best later precision 2/3.
  EXPECT_NEAR(ComputePrecisionRecall(Outcomes()).area, 0.25 * 1.0 + 0.25 * 2.0 / 3.0, 1e-12);
}

TEST(PrecisionRecallTest, PointAtAThreshold) {
  const PrecisionRecallPoint strict = PointAt(Outcomes(), 0.85);
  EXPECT_DOUBLE_EQ(strict.precision, 1.0);
  EXPECT_DOUBLE_EQ(strict.recall, 0.25);
  const PrecisionRecallPoint none = PointAt(Outcomes(), 0.95);
  EXPECT_DOUBLE_EQ(none.precision, 1.0);  // nothing accepted: no false detection
  EXPECT_DOUBLE_EQ(none.recall, 0.0);
  EXPECT_DOUBLE_EQ(PointAt(Outcomes(), 0.0).precision, 0.5);
}

TEST(PrecisionRecallTest, PlotIsDrawn) {
  const PrecisionRecallCurve curve = ComputePrecisionRecall(Outcomes());
  const cv::Mat plot = DrawPrecisionRecall(curve, PointAt(Outcomes(), 0.5));
  ASSERT_EQ(plot.type(), CV_8UC3);
  EXPECT_GT(plot.cols, 400);
  // The curve's colour appears in the plot.
  int curve_pixels = 0;
  for (int y = 0; y < plot.rows; ++y) {
    for (int x = 0; x < plot.cols; ++x)
      curve_pixels += plot.at<cv::Vec3b>(y, x) == cv::Vec3b(200, 110, 30);
  }
  EXPECT_GT(curve_pixels, 100);
}

TEST(PrecisionRecallTest, NoDetectionsGiveAnEmptyCurve) {
  const PrecisionRecallCurve curve = ComputePrecisionRecall({Outcome(true, false, 0.0, false)});
  EXPECT_TRUE(curve.points.empty());
  EXPECT_EQ(curve.targets, 1);
  EXPECT_DOUBLE_EQ(curve.area, 0.0);
}

}  // namespace
}  // namespace layermod
