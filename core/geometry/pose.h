// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace layermod {

// Rigid transform from model to camera coordinates: x_in_cam = R * x_in_model + t (t in mm).
struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();

  Eigen::Vector3d operator*(const Eigen::Vector3d& x) const { return R * x + t; }
  Pose operator*(const Pose& other) const { return {R * other.R, R * other.t + t}; }
  Pose Inverse() const { return {R.transpose(), -(R.transpose() * t)}; }
};

// Degrees to radians and back, so angle units show in names.
constexpr double kPi = 3.14159265358979323846;
constexpr double DegToRad(double angle_deg) { return angle_deg * kPi / 180.0; }
constexpr double RadToDeg(double angle_rad) { return angle_rad * 180.0 / kPi; }

}  // namespace layermod
