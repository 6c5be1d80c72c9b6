// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace layermod {

// Flat triangle soup for the rasterizer: model coordinates in mm, per-vertex colour in [0, 1]
// (RGB), indices into `positions`. Built once per model from the OpenMesh mesh.
struct RenderMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> colors;  // same size as positions
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace layermod
