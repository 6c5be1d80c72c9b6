// SPDX-License-Identifier: MIT
#include "mesh/vertex_clustering.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <unordered_map>

#include "util/error.h"

namespace layermod {
namespace {

std::uint64_t CellKey(const Eigen::Vector3f& position, const Eigen::Vector3f& origin,
                      double cell_mm) {
  const auto index = [&](int axis) {
    return static_cast<std::uint64_t>(std::floor((position[axis] - origin[axis]) / cell_mm)) &
           0x1FFFFFu;  // 21 bits
  };
  return index(0) | (index(1) << 21) | (index(2) << 42);
}

// A triangle up to rotation of its corners (which keeps the winding).
std::array<std::uint32_t, 3> Canonical(std::array<std::uint32_t, 3> corners) {
  const auto first = std::min_element(corners.begin(), corners.end());
  std::rotate(corners.begin(), first, corners.end());
  return corners;
}

}  // namespace

RenderMesh ClusterVertices(const RenderMesh& mesh, double cell_mm) {
  if (!(cell_mm > 0.0) || !std::isfinite(cell_mm)) {
    throw Error("vertex clustering: the cell size must be positive");
  }
  if (mesh.positions.empty()) return mesh;
  Eigen::Vector3f origin = mesh.positions.front();
  for (const Eigen::Vector3f& position : mesh.positions) origin = origin.cwiseMin(position);

  std::unordered_map<std::uint64_t, std::uint32_t> cluster_of_cell;
  std::vector<std::uint32_t> cluster_of_vertex(mesh.positions.size());
  std::vector<Eigen::Vector3d> position_sums;
  std::vector<Eigen::Vector3d> color_sums;
  std::vector<int> counts;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto [entry, added] = cluster_of_cell.try_emplace(
        CellKey(mesh.positions[v], origin, cell_mm), static_cast<std::uint32_t>(counts.size()));
    if (added) {
      position_sums.emplace_back(Eigen::Vector3d::Zero());
      color_sums.emplace_back(Eigen::Vector3d::Zero());
      counts.push_back(0);
    }
    const std::uint32_t cluster = entry->second;
    cluster_of_vertex[v] = cluster;
    position_sums[cluster] += mesh.positions[v].cast<double>();
    color_sums[cluster] += mesh.colors[v].cast<double>();
    ++counts[cluster];
  }

  RenderMesh clustered;
  clustered.positions.reserve(counts.size());
  clustered.colors.reserve(counts.size());
  for (std::size_t c = 0; c < counts.size(); ++c) {
    clustered.positions.push_back((position_sums[c] / counts[c]).cast<float>());
    clustered.colors.push_back((color_sums[c] / counts[c]).cast<float>());
  }
  std::set<std::array<std::uint32_t, 3>> seen;
  for (const auto& triangle : mesh.triangles) {
    const std::array<std::uint32_t, 3> corners = {cluster_of_vertex[triangle[0]],
                                                  cluster_of_vertex[triangle[1]],
                                                  cluster_of_vertex[triangle[2]]};
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) continue;
    if (seen.insert(Canonical(corners)).second) clustered.triangles.push_back(corners);
  }
  return clustered;
}

RenderMesh SimplifyToTriangleCount(const RenderMesh& mesh, std::size_t max_triangles,
                                   double min_cell_mm) {
  if (mesh.triangles.size() <= max_triangles) return mesh;
  RenderMesh clustered;
  for (double cell = min_cell_mm;; cell *= 1.25) {
    clustered = ClusterVertices(mesh, cell);
    if (clustered.triangles.size() <= max_triangles || clustered.triangles.empty()) break;
  }
  return clustered;
}

}  // namespace layermod
