// SPDX-License-Identifier: MIT
#include "synth/primitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "geometry/pose.h"
#include "util/error.h"

namespace layermod {
namespace {

// Volume by the divergence theorem: positive when every face winds outwards.
double SignedVolume(const RenderMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.positions[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.positions[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.positions[t[2]].cast<double>();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Closed and consistently oriented: every directed edge appears once and its reverse once.
bool IsClosedManifold(const RenderMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    if (count != 1 || edges.count({edge.second, edge.first}) == 0) return false;
  }
  return true;
}

TEST(PrimitivesTest, BoxStandsOnZeroAndIsClosedOutwards) {
  const RenderMesh box = MakeBoxMesh({40.0f, 60.0f, 30.0f}, {0.5f, 0.2f, 0.1f});
  EXPECT_EQ(box.positions.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_EQ(box.colors.size(), box.positions.size());
  EXPECT_NEAR(SignedVolume(box), 40.0 * 60.0 * 30.0, 1e-6);
  EXPECT_TRUE(IsClosedManifold(box));
  float min_z = 1e9f;
  float max_x = -1e9f;
  for (const auto& p : box.positions) {
    min_z = std::min(min_z, p.z());
    max_x = std::max(max_x, p.x());
  }
  EXPECT_EQ(min_z, 0.0f);
  EXPECT_EQ(max_x, 20.0f);
}

TEST(PrimitivesTest, CylinderIsAClosedPrism) {
  const int segments = 24;
  const RenderMesh cylinder = MakeCylinderMesh(10.0f, 50.0f, segments, {1.0f, 1.0f, 1.0f});
  const double polygon_area = 0.5 * segments * 100.0 * std::sin(2.0 * kPi / segments);
  EXPECT_NEAR(SignedVolume(cylinder), polygon_area * 50.0, 1e-3);
  EXPECT_TRUE(IsClosedManifold(cylinder));
}

TEST(PrimitivesTest, RefusesDegenerateSizes) {
  EXPECT_THROW(MakeBoxMesh({0.0f, 1.0f, 1.0f}, {1.0f, 1.0f, 1.0f}), Error);
  EXPECT_THROW(MakeCylinderMesh(1.0f, 1.0f, 2, {1.0f, 1.0f, 1.0f}), Error);
}

}  // namespace
}  // namespace layermod
