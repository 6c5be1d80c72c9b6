// SPDX-License-Identifier: MIT
#include "mesh/vertex_clustering.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "util/error.h"

namespace layermod {
namespace {

// A UV sphere of `radius` mm, outward winding, red.
RenderMesh Sphere(double radius, int rings, int segments) {
  RenderMesh mesh;
  for (int r = 0; r <= rings; ++r) {
    const double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * M_PI * s / segments;
      mesh.positions.emplace_back(static_cast<float>(radius * std::sin(theta) * std::cos(phi)),
                                  static_cast<float>(radius * std::sin(theta) * std::sin(phi)),
                                  static_cast<float>(radius * std::cos(theta)));
      mesh.colors.emplace_back(1.0f, 0.0f, 0.0f);
    }
  }
  const auto index = [&](int r, int s) {
    return static_cast<std::uint32_t>(r * segments + (s % segments));
  };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      mesh.triangles.push_back({index(r, s), index(r + 1, s), index(r + 1, s + 1)});
      mesh.triangles.push_back({index(r, s), index(r + 1, s + 1), index(r, s + 1)});
    }
  }
  return mesh;
}

Eigen::Vector3f FaceNormal(const RenderMesh& mesh, const std::array<std::uint32_t, 3>& triangle) {
  const Eigen::Vector3f& a = mesh.positions[triangle[0]];
  return (mesh.positions[triangle[1]] - a).cross(mesh.positions[triangle[2]] - a);
}

TEST(VertexClusteringTest, MergesNearbyVerticesAndKeepsTheShapeAndWinding) {
  const RenderMesh fine = Sphere(50.0, 60, 120);
  const RenderMesh coarse = ClusterVertices(fine, 8.0);
  EXPECT_LT(coarse.triangles.size(), fine.triangles.size() / 4);
  EXPECT_GT(coarse.triangles.size(), 100u);
  ASSERT_EQ(coarse.colors.size(), coarse.positions.size());
  for (std::size_t v = 0; v < coarse.positions.size(); ++v) {
    // Means of points on the sphere within one 8 mm cube: inside it by at most a few mm.
    EXPECT_NEAR(coarse.positions[v].norm(), 50.0f, 3.0f);
    EXPECT_FLOAT_EQ(coarse.colors[v].x(), 1.0f);
  }
  int outward = 0;
  for (const auto& triangle : coarse.triangles) {
    EXPECT_NE(triangle[0], triangle[1]);
    EXPECT_NE(triangle[1], triangle[2]);
    EXPECT_NE(triangle[0], triangle[2]);
    const Eigen::Vector3f centre = (coarse.positions[triangle[0]] + coarse.positions[triangle[1]] +
                                    coarse.positions[triangle[2]]) /
                                   3.0f;
    outward += FaceNormal(coarse, triangle).dot(centre) > 0.0f ? 1 : 0;
  }
  // Clustering can fold a few triangles near the poles; the surface stays outward.
  EXPECT_GT(outward, static_cast<int>(coarse.triangles.size() * 95 / 100));
}

TEST(VertexClusteringTest, SimplifiesToATriangleBudget) {
  const RenderMesh fine = Sphere(50.0, 60, 120);
  const RenderMesh simplified = SimplifyToTriangleCount(fine, 2000, 0.5);
  EXPECT_LE(simplified.triangles.size(), 2000u);
  EXPECT_GT(simplified.triangles.size(), 500u);  // the finest cell that fits, not far coarser
  const RenderMesh untouched = SimplifyToTriangleCount(fine, fine.triangles.size(), 0.5);
  EXPECT_EQ(untouched.triangles, fine.triangles);
  EXPECT_THROW(ClusterVertices(fine, 0.0), Error);
  EXPECT_THROW(ClusterVertices(fine, std::nan("")), Error);
  EXPECT_TRUE(ClusterVertices(RenderMesh{}, 1.0).triangles.empty());
}

}  // namespace
}  // namespace layermod
