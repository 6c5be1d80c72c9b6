// SPDX-License-Identifier: MIT
// The convex hull of a point set: the shape a part presents to a table it lies on (see
// resting_poses.h).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

namespace layermod {

// A closed convex triangle mesh; every triangle winds counter-clockwise seen from outside.
struct ConvexHull {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // indices into vertices

  bool Empty() const { return triangles.empty(); }
};

// The convex hull of `points` (quickhull). Duplicate points, and points within rounding distance
// of a hull plane, are not hull vertices; a flat side made of several triangles keeps them all
// (MergeCoplanarTriangles joins them). Empty when the points span no volume (fewer than four, all
// on one plane). Throws Error on non-finite coordinates.
ConvexHull ComputeConvexHull(const std::vector<Eigen::Vector3d>& points);

// The centroid of the solid the hull encloses. Throws Error when the hull is empty.
Eigen::Vector3d HullVolumeCentroid(const ConvexHull& hull);

}  // namespace layermod
