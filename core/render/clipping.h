// SPDX-License-Identifier: MIT
// Internal to the rasterizer: clipping triangles to the near plane and the guard band.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "render/screen_projection.h"

namespace layermod::render_internal {

// A convex polygon in camera space. Clipping a triangle by the five planes adds at most one
// vertex per plane.
struct ClipPolygon {
  static constexpr int kMaxVertices = 3 + kClipPlaneCount;
  std::array<Eigen::Vector3f, kMaxVertices> vertices;
  int size = 0;
};

// Clips triangle abc against the planes whose bits are set in `planes` (ClipBit values).
// Intersection points are computed from the inside end of each edge towards the outside end,
// so an edge shared by two triangles is cut at bit-identical points (no cracks).
ClipPolygon ClipTriangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                         const Eigen::Vector3f& c, std::uint32_t planes,
                         const ScreenProjection& projection);

}  // namespace layermod::render_internal
