// SPDX-License-Identifier: MIT
#include "mesh/decimation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/pose.h"
#include "util/error.h"

namespace layermod {
namespace {

// A UV sphere of `radius_mm` with rings x segments quads split into triangles, coloured by
// height so colours can be checked after simplification.
TriMesh UvSphere(double radius_mm, int rings, int segments) {
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> vertices;
  const TriMesh::VertexHandle north = mesh.add_vertex(TriMesh::Point(0.0, 0.0, radius_mm));
  for (int ring = 1; ring < rings; ++ring) {
    const double polar = kPi * ring / rings;
    for (int segment = 0; segment < segments; ++segment) {
      const double azimuth = 2.0 * kPi * segment / segments;
      vertices.push_back(mesh.add_vertex(TriMesh::Point(
          radius_mm * std::sin(polar) * std::cos(azimuth),
          radius_mm * std::sin(polar) * std::sin(azimuth), radius_mm * std::cos(polar))));
    }
  }
  const TriMesh::VertexHandle south = mesh.add_vertex(TriMesh::Point(0.0, 0.0, -radius_mm));
  auto at = [&](int ring, int segment) {
    return vertices[static_cast<std::size_t>((ring - 1) * segments + (segment % segments))];
  };
  for (int segment = 0; segment < segments; ++segment) {
    mesh.add_face(north, at(1, segment), at(1, segment + 1));
    mesh.add_face(south, at(rings - 1, segment + 1), at(rings - 1, segment));
    for (int ring = 1; ring + 1 < rings; ++ring) {
      mesh.add_face(at(ring, segment), at(ring + 1, segment), at(ring + 1, segment + 1));
      mesh.add_face(at(ring, segment), at(ring + 1, segment + 1), at(ring, segment + 1));
    }
  }
  for (const auto vertex : mesh.vertices()) {
    const bool upper = mesh.point(vertex)[2] >= 0.0;
    mesh.set_color(vertex, upper ? TriMesh::Color(200, 30, 30) : TriMesh::Color(30, 30, 200));
  }
  return mesh;
}

TEST(DecimateMeshTest, KeepsTheSurfaceWithinTheErrorBound) {
  const TriMesh dense = UvSphere(50.0, 100, 100);  // 19800 triangles
  ASSERT_GT(dense.n_faces(), 19000u);
  const TriMesh simplified = DecimateMesh(dense, 5000, 0.5);
  EXPECT_LE(simplified.n_faces(), 5000u);
  EXPECT_GT(simplified.n_faces(), 500u);
  for (const auto vertex : simplified.vertices()) {
    const double distance = simplified.point(vertex).norm();
    // The quadric bound holds for vertices; the chords between them sag by less than 0.5 mm too.
    EXPECT_NEAR(distance, 50.0, 0.5);
    const bool upper = simplified.point(vertex)[2] >= 0.0;
    EXPECT_EQ(simplified.color(vertex)[0], upper ? 200 : 30);
  }
}

TEST(DecimateMeshTest, ErrorBoundStopsBeforeTheTriangleBudget) {
  const TriMesh dense = UvSphere(50.0, 60, 60);
  // A tiny bound allows almost no collapse on a curved surface: far more than 100 faces remain.
  EXPECT_GT(DecimateMesh(dense, 100, 0.001).n_faces(), 1000u);
}

TEST(DecimateMeshTest, SmallMeshesAreUnchangedAndBadArgumentsThrow) {
  const TriMesh small = UvSphere(10.0, 8, 8);
  EXPECT_EQ(DecimateMesh(small, 1000, 0.5).n_faces(), small.n_faces());
  EXPECT_THROW(DecimateMesh(small, 0, 0.5), Error);
  EXPECT_THROW(DecimateMesh(small, 10, 0.0), Error);
  EXPECT_THROW(DecimateMesh(small, 10, std::nan("")), Error);
}

}  // namespace
}  // namespace layermod
