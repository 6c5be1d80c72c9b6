// SPDX-License-Identifier: MIT
#include "geometry/up_axis.h"

#include <Eigen/Geometry>
#include <cmath>

#include "util/error.h"

namespace layermod {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

}  // namespace

const std::vector<std::string>& UpAxisNames() {
  static const std::vector<std::string> names = {"+x", "-x", "+y", "-y", "+z", "-z"};
  return names;
}

Eigen::Matrix3d UprightFromUpAxis(std::string_view axis) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  if (axis == "+z") return Eigen::Matrix3d::Identity();
  if (axis == "-z") return AngleAxisd(2.0 * kHalfPi, Vector3d::UnitX()).toRotationMatrix();
  if (axis == "+x") return AngleAxisd(-kHalfPi, Vector3d::UnitY()).toRotationMatrix();
  if (axis == "-x") return AngleAxisd(kHalfPi, Vector3d::UnitY()).toRotationMatrix();
  if (axis == "+y") return AngleAxisd(kHalfPi, Vector3d::UnitX()).toRotationMatrix();
  if (axis == "-y") return AngleAxisd(-kHalfPi, Vector3d::UnitX()).toRotationMatrix();
  throw Error("up axis: '" + std::string(axis) + "' is not one of +x, -x, +y, -y, +z, -z");
}

std::optional<std::string> UpAxisName(const Eigen::Matrix3d& upright_from_model) {
  for (const std::string& name : UpAxisNames()) {
    if (upright_from_model.isApprox(UprightFromUpAxis(name), 1e-9)) return name;
  }
  return std::nullopt;
}

Eigen::Matrix3d UprightFromUpDirection(const Eigen::Vector3d& up_in_model) {
  if (!up_in_model.allFinite() || up_in_model.norm() < 1e-12) {
    throw Error("up direction: must be a finite, non-zero vector");
  }
  return Eigen::Quaterniond::FromTwoVectors(up_in_model.normalized(), Eigen::Vector3d::UnitZ())
      .toRotationMatrix();
}

Eigen::Vector3d UpDirectionInModel(const Eigen::Matrix3d& upright_from_model) {
  return upright_from_model.transpose() * Eigen::Vector3d::UnitZ();
}

void ValidateRotation(const Eigen::Matrix3d& rotation, std::string_view what) {
  const bool finite = rotation.allFinite();
  const bool orthonormal =
      finite && (rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-6;
  if (!orthonormal || std::abs(rotation.determinant() - 1.0) > 1e-6) {
    throw Error(std::string(what) + ": not a rotation (rows must be orthonormal, determinant +1)");
  }
}

}  // namespace layermod
