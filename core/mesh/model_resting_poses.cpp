// SPDX-License-Identifier: MIT
#include "mesh/model_resting_poses.h"

#include <array>
#include <vector>

namespace layermod {

RestingPoses SuggestRestingPoses(const Model& model) {
  const TriMesh& mesh = model.mesh;
  std::vector<Eigen::Vector3d> vertices;
  vertices.reserve(mesh.n_vertices());
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    vertices.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces()) {
    std::array<int, 3> triangle{};
    int corner = 0;
    for (const auto vh : mesh.fv_range(fh)) {
      if (corner < 3) triangle[corner] = vh.idx();
      ++corner;
    }
    if (corner == 3) triangles.push_back(triangle);
  }
  return FindRestingPoses(vertices, triangles);
}

}  // namespace layermod
