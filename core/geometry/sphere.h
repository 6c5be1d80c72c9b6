// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <vector>

namespace layermod {

struct Sphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius_mm = 0.0;
};

// Exact minimal enclosing sphere of `points` (Welzl's algorithm with move-to-front, expected linear
// time). Throws Error on an empty set or non-finite coordinates.
Sphere MinimalEnclosingSphere(const std::vector<Eigen::Vector3d>& points);

}  // namespace layermod
