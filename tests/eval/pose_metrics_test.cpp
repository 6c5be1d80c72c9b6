// SPDX-License-Identifier: MIT
#include "eval/pose_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/test_cameras.h"
#include "util/error.h"

namespace layermod {
namespace {

// The 8 corners of a 100 x 60 x 40 mm box centred on the origin: no symmetry maps the corner set
// onto itself except the box's own 180-degree turns.
std::vector<Eigen::Vector3d> BoxCorners() {
  std::vector<Eigen::Vector3d> corners;
  for (const double x : {-50.0, 50.0}) {
    for (const double y : {-30.0, 30.0}) {
      for (const double z : {-20.0, 20.0}) corners.emplace_back(x, y, z);
    }
  }
  return corners;
}

Pose At(const Eigen::Vector3d& t, const Eigen::Matrix3d& R = Eigen::Matrix3d::Identity()) {
  return {R, t};
}

Eigen::Matrix3d RotZ(double angle_deg) {
  return Eigen::AngleAxisd(DegToRad(angle_deg), Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

TEST(PoseMetricsTest, IdentityPoseHasNoError) {
  const Pose pose = At({10.0, -20.0, 800.0}, RotZ(30.0));
  EXPECT_EQ(AddErrorMm(BoxCorners(), pose, pose), 0.0);
  EXPECT_EQ(AddSErrorMm(BoxCorners(), PointKdTree(BoxCorners()), pose, pose), 0.0);
  EXPECT_EQ(Projection2DErrorPx(BoxCorners(), pose, pose, test::RoundVgaCamera()), 0.0);
}

TEST(PoseMetricsTest, PureTranslationMovesEveryPointByItsLength) {
  // Every point moves by (3, 4, 0): 5 mm.
  EXPECT_NEAR(AddErrorMm(BoxCorners(), At({3.0, 4.0, 800.0}), At({0.0, 0.0, 800.0})), 5.0, 1e-12);
}

TEST(PoseMetricsTest, RotationAboutTheCentreGivesTheMeanChordLength) {
  // 90 degrees about z: a corner at radius r in the xy plane moves by r * sqrt(2); all corners
  // have r = sqrt(50^2 + 30^2).
  const double expected = std::sqrt(50.0 * 50.0 + 30.0 * 30.0) * std::sqrt(2.0);
  EXPECT_NEAR(AddErrorMm(BoxCorners(), At({0, 0, 800}, RotZ(90.0)), At({0, 0, 800})), expected,
              1e-9);
}

TEST(PoseMetricsTest, AddSForgivesARotationByTheObjectsSymmetry) {
  // The box maps onto itself under a half turn about z; ADD sees every corner move.
  const auto corners = BoxCorners();
  const PointKdTree tree(corners);
  const Pose truth = At({0, 0, 800});
  const Pose turned = At({0, 0, 800}, RotZ(180.0));
  EXPECT_NEAR(AddSErrorMm(corners, tree, turned, truth), 0.0, 1e-9);
  EXPECT_NEAR(AddErrorMm(corners, turned, truth), 2.0 * std::sqrt(50.0 * 50.0 + 30.0 * 30.0), 1e-9);
}

TEST(PoseMetricsTest, AddSOfAKnownOffsetIsTheNearestPointDistance) {
  // Shifted 10 mm along x the estimated corners lie at x = -40 and x = 60: each true corner
  // (x = -50, x = 50) is 10 mm from its own copy, so ADD-S = ADD = 10 mm.
  const auto corners = BoxCorners();
  EXPECT_NEAR(AddSErrorMm(corners, PointKdTree(corners), At({10, 0, 800}), At({0, 0, 800})), 10.0,
              1e-12);
  // Shifted 60 mm the estimated corners lie at x = 10 and x = 110: the true corners at x = -50
  // are 60 mm from x = 10, those at x = 50 are 40 mm from x = 10 (not their own copy): 50 mm.
  EXPECT_NEAR(AddSErrorMm(corners, PointKdTree(corners), At({60, 0, 800}), At({0, 0, 800})), 50.0,
              1e-12);
}

TEST(PoseMetricsTest, ProjectionErrorOfALateralShift) {
  // At z = 1000 mm with f = 500 px, 10 mm sideways is 5 px for every point.
  const std::vector<Eigen::Vector3d> points = {{0, 0, 0}, {0, 0, 0}};
  EXPECT_NEAR(
      Projection2DErrorPx(points, At({10, 0, 1000}), At({0, 0, 1000}), test::RoundVgaCamera()), 5.0,
      1e-12);
}

TEST(PoseMetricsTest, ProjectionErrorIsInfiniteBehindTheCamera) {
  EXPECT_TRUE(std::isinf(Projection2DErrorPx(BoxCorners(), At({0, 0, -800}), At({0, 0, 800}),
                                             test::RoundVgaCamera())));
  EXPECT_TRUE(ProjectedBox(BoxCorners(), At({0, 0, -800}), test::RoundVgaCamera()).empty());
}

TEST(PoseMetricsTest, ProjectedBoxOfAFrontalSquare) {
  // Corners at +-50 mm, z = 1000: +-25 px around the principal point.
  const std::vector<Eigen::Vector3d> square = {{-50, -50, 0}, {50, 50, 0}};
  EXPECT_EQ(ProjectedBox(square, At({0, 0, 1000}), test::RoundVgaCamera()),
            cv::Rect(295, 215, 50, 50));
}

TEST(PoseMetricsTest, BoxIoU) {
  EXPECT_DOUBLE_EQ(BoxIoU({0, 0, 10, 10}, {0, 0, 10, 10}), 1.0);
  EXPECT_DOUBLE_EQ(BoxIoU({0, 0, 10, 10}, {5, 0, 10, 10}), 50.0 / 150.0);
  EXPECT_DOUBLE_EQ(BoxIoU({0, 0, 10, 10}, {20, 20, 5, 5}), 0.0);
  EXPECT_DOUBLE_EQ(BoxIoU({}, {}), 0.0);
}

TEST(PoseMetricsTest, RefusesAnEmptyModel) { EXPECT_THROW(AddErrorMm({}, Pose{}, Pose{}), Error); }

}  // namespace
}  // namespace layermod
