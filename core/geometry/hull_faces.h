// SPDX-License-Identifier: MIT
// The flat sides of a convex hull: a part lying on a table touches it with one of them.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/convex_hull.h"

namespace layermod {

// One flat side of a hull: a convex polygon in the plane outward_normal . x = plane_offset.
struct HullFace {
  Eigen::Vector3d outward_normal = Eigen::Vector3d::UnitZ();  // unit
  double plane_offset = 0.0;
  std::vector<Eigen::Vector3d> polygon;  // corners, counter-clockwise seen from outside
  // neighbours[i]: the faces (indices into MergeCoplanarTriangles' result) across the hull edges
  // along side i of the polygon (corner i to corner i + 1), each once. Usually one; a side that
  // borders a tessellated curve has several. Empty for a side no hull edge was matched to.
  std::vector<std::vector<int>> neighbours;
};

// Hull triangles with normals within this angle of a face's largest triangle, and corners on its
// plane, form one face: CAD and scanned meshes tessellate a flat side into many slightly tilted
// triangles, and a part rests on the whole side, not on one triangle of it.
inline constexpr double kCoplanarAngleDeg = 1.0;

// The hull's flat faces (adjacent triangles joined as described at kCoplanarAngleDeg) and which
// of them meet along each side.
std::vector<HullFace> MergeCoplanarTriangles(const ConvexHull& hull);

}  // namespace layermod
