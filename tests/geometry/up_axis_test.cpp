// SPDX-License-Identifier: MIT
#include "geometry/up_axis.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/views.h"
#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(UpAxisTest, EachNamedAxisIsTurnedToPlusZ) {
  const std::vector<std::pair<std::string, Eigen::Vector3d>> axes = {
      {"+x", Eigen::Vector3d::UnitX()}, {"-x", -Eigen::Vector3d::UnitX()},
      {"+y", Eigen::Vector3d::UnitY()}, {"-y", -Eigen::Vector3d::UnitY()},
      {"+z", Eigen::Vector3d::UnitZ()}, {"-z", -Eigen::Vector3d::UnitZ()}};
  for (const auto& [name, axis] : axes) {
    const Eigen::Matrix3d upright = UprightFromUpAxis(name);
    EXPECT_TRUE((upright * axis).isApprox(Eigen::Vector3d::UnitZ(), 1e-12)) << name;
    EXPECT_NEAR(upright.determinant(), 1.0, 1e-12) << name;
    EXPECT_EQ(UpAxisName(upright), name);
    EXPECT_TRUE(UpDirectionInModel(upright).isApprox(axis, 1e-12)) << name;
  }
  EXPECT_EQ(UpAxisName(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix()),
            std::nullopt);
  EXPECT_NE(test::ThrownMessage<Error>([] { UprightFromUpAxis("up"); }).find("'up'"),
            std::string::npos);
}

TEST(UpAxisTest, ATiltedUpDirectionIsTurnedToPlusZ) {
  for (const Eigen::Vector3d& up :
       {Eigen::Vector3d(0.2, -0.7, 0.7), Eigen::Vector3d(0, 0, -3), Eigen::Vector3d(0, 0, 1)}) {
    const Eigen::Matrix3d upright = UprightFromUpDirection(up);
    EXPECT_NO_THROW(ValidateRotation(upright, "upright"));
    EXPECT_TRUE((upright * up.normalized()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
    EXPECT_TRUE(UpDirectionInModel(upright).isApprox(up.normalized(), 1e-12));
  }
  EXPECT_THROW(UprightFromUpDirection(Eigen::Vector3d::Zero()), Error);
  EXPECT_THROW(UprightFromUpDirection(Eigen::Vector3d(std::nan(""), 0, 1)), Error);
}

TEST(UpAxisTest, RejectsWhatIsNotARotation) {
  Eigen::Matrix3d mirror = Eigen::Matrix3d::Identity();
  mirror(2, 2) = -1.0;
  EXPECT_NE(test::ThrownMessage<Error>([&] {
              ValidateRotation(mirror, "up rotation");
            }).find("up rotation: not a rotation"),
            std::string::npos);
  EXPECT_NO_THROW(ValidateRotation(UprightFromUpAxis("-y"), "up rotation"));
}

// A view of a -Z-up model with --up-axis -z sees it as a view of the +Z-up model with +z: the
// camera is above the part's real top either way.
TEST(UpAxisTest, ViewsAreMeasuredInTheUprightFrame) {
  const Eigen::Matrix3d flip = UprightFromUpAxis("-z");  // model_b = flip^T * model_a
  const Eigen::Vector3d centre_a(5.0, -3.0, 20.0);
  const Eigen::Vector3d centre_b = flip.transpose() * centre_a;
  const ViewAngles view{40.0, 30.0, 10.0};
  const Pose pose_a = CamFromModelForView(view, centre_a, 700.0);
  const Pose pose_b = CamFromModelForView(view, centre_b, 700.0, flip);
  // The same physical point seen at the same place in the camera.
  const Eigen::Vector3d point_a(12.0, 7.0, 35.0);
  const Eigen::Vector3d point_b = flip.transpose() * point_a;
  EXPECT_TRUE((pose_a * point_a).isApprox(pose_b * point_b, 1e-9));
  // And the sphere centre on the optical axis at the layer depth.
  EXPECT_TRUE((pose_b * centre_b).isApprox(Eigen::Vector3d(0, 0, 700.0), 1e-9));
}

}  // namespace
}  // namespace layermod
