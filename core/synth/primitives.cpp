// SPDX-License-Identifier: MIT
#include "synth/primitives.h"

#include <cmath>

#include "geometry/pose.h"
#include "util/error.h"

namespace layermod {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

void AddQuad(RenderMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  mesh.triangles.push_back(Triangle{a, b, c});
  mesh.triangles.push_back(Triangle{a, c, d});
}

void Paint(RenderMesh& mesh, const Eigen::Vector3f& color) {
  mesh.colors.assign(mesh.positions.size(), color);
}

}  // namespace

RenderMesh MakeBoxMesh(const Eigen::Vector3f& size_mm, const Eigen::Vector3f& color) {
  if (!(size_mm.minCoeff() > 0.0f)) throw Error("box: sizes must be positive");
  RenderMesh mesh;
  const Eigen::Vector3f half(size_mm.x() / 2, size_mm.y() / 2, size_mm.z());
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                                i & 4 ? half.z() : 0.0f);
  }
  // Outward winding (counter-clockwise seen from outside).
  AddQuad(mesh, 0, 2, 3, 1);  // bottom
  AddQuad(mesh, 4, 5, 7, 6);  // top
  AddQuad(mesh, 0, 1, 5, 4);  // -y
  AddQuad(mesh, 2, 6, 7, 3);  // +y
  AddQuad(mesh, 0, 4, 6, 2);  // -x
  AddQuad(mesh, 1, 3, 7, 5);  // +x
  Paint(mesh, color);
  return mesh;
}

RenderMesh MakeCylinderMesh(float radius_mm, float height_mm, int segments,
                            const Eigen::Vector3f& color) {
  if (!(radius_mm > 0.0f && height_mm > 0.0f) || segments < 3) {
    throw Error("cylinder: radius and height must be positive, segments at least 3");
  }
  RenderMesh mesh;
  const auto n = static_cast<std::uint32_t>(segments);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double angle = 2.0 * kPi * i / n;
    const float x = radius_mm * static_cast<float>(std::cos(angle));
    const float y = radius_mm * static_cast<float>(std::sin(angle));
    // Rim vertices interleaved: 2i on the bottom, 2i + 1 on top.
    mesh.positions.emplace_back(x, y, 0.0f);
    mesh.positions.emplace_back(x, y, height_mm);
  }
  const std::uint32_t bottom_centre = 2 * n;
  const std::uint32_t top_centre = 2 * n + 1;
  mesh.positions.emplace_back(0.0f, 0.0f, 0.0f);
  mesh.positions.emplace_back(0.0f, 0.0f, height_mm);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    AddQuad(mesh, 2 * i, 2 * j, 2 * j + 1, 2 * i + 1);
    mesh.triangles.push_back(Triangle{bottom_centre, 2 * j, 2 * i});
    mesh.triangles.push_back(Triangle{top_centre, 2 * i + 1, 2 * j + 1});
  }
  Paint(mesh, color);
  return mesh;
}

}  // namespace layermod
