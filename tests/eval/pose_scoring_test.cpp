// SPDX-License-Identifier: MIT
#include "eval/pose_scoring.h"

#include <gtest/gtest.h>

#include "support/test_cameras.h"
#include "util/error.h"

namespace layermod {
namespace {

// A 100 mm rod along x (diameter 100 mm): half-turns about x map it onto itself.
EvalModel Rod(bool symmetric) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i <= 10; ++i) points.emplace_back(-50.0 + 10.0 * i, 0.0, 0.0);
  return EvalModel(7, 100.0, symmetric, points);
}

Pose At(double x, double y, double z, double turn_about_z_deg = 0.0) {
  return {
      Eigen::AngleAxisd(DegToRad(turn_about_z_deg), Eigen::Vector3d::UnitZ()).toRotationMatrix(),
      {x, y, z}};
}

TEST(PoseScoringTest, CorrectAtTheThresholdAndNotBeyond) {
  const EvalModel rod = Rod(false);
  const EvalMetricOptions options;  // km 0.1: 10 mm for the rod
  const PoseScore at =
      ScorePose(rod, At(0, 10, 1000), At(0, 0, 1000), test::RoundVgaCamera(), options);
  EXPECT_NEAR(at.error_mm, 10.0, 1e-12);
  EXPECT_TRUE(at.correct);
  EXPECT_FALSE(at.symmetric_metric);
  const PoseScore beyond =
      ScorePose(rod, At(0, 10.5, 1000), At(0, 0, 1000), test::RoundVgaCamera(), options);
  EXPECT_FALSE(beyond.correct);
}

TEST(PoseScoringTest, Proj2DAndBoxChecks) {
  const EvalModel rod = Rod(false);
  EvalMetricOptions options;
  // 10 mm at 1000 mm with f = 500: 5 px, exactly at the threshold.
  const PoseScore score =
      ScorePose(rod, At(0, 10, 1000), At(0, 0, 1000), test::RoundVgaCamera(), options);
  EXPECT_NEAR(score.proj2d_px, 5.0, 1e-12);
  EXPECT_TRUE(score.proj2d_correct);
  // The rod's boxes are 50 x 0 px lines: no area, so no overlap.
  EXPECT_EQ(score.box_iou, 0.0);
  EXPECT_FALSE(score.box_correct);
}

TEST(PoseScoringTest, SymmetricObjectsUseAddS) {
  const PoseScore turned_plain =
      ScorePose(Rod(false), At(0, 0, 1000, 180.0), At(0, 0, 1000), test::RoundVgaCamera(), {});
  EXPECT_FALSE(turned_plain.correct);
  const PoseScore turned_symmetric =
      ScorePose(Rod(true), At(0, 0, 1000, 180.0), At(0, 0, 1000), test::RoundVgaCamera(), {});
  EXPECT_TRUE(turned_symmetric.symmetric_metric);
  EXPECT_NEAR(turned_symmetric.error_mm, 0.0, 1e-9);
  EXPECT_TRUE(turned_symmetric.correct);
}

TEST(PoseScoringTest, KmScalesTheThreshold) {
  EvalMetricOptions options;
  options.km = 0.2;
  EXPECT_TRUE(
      ScorePose(Rod(false), At(0, 15, 1000), At(0, 0, 1000), test::RoundVgaCamera(), options)
          .correct);
}

TEST(PoseScoringTest, ValidatesOptions) {
  EvalMetricOptions options;
  options.km = 0.0;
  EXPECT_THROW(options.Validate(), Error);
  options = {};
  options.min_box_iou = 1.5;
  EXPECT_THROW(options.Validate(), Error);
  EXPECT_THROW(EvalModel(1, 0.0, false, {Eigen::Vector3d::Zero()}), Error);
}

}  // namespace
}  // namespace layermod
