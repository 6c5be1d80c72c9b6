// SPDX-License-Identifier: MIT
#include "mesh/sample_part.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "support/matchers.h"
#include "support/test_paths.h"

namespace layermod {
namespace {

using Triangle = std::array<Eigen::Vector3d, 3>;

Eigen::Vector3d ToEigen(const TriMesh::Point& p) { return {p[0], p[1], p[2]}; }

std::vector<Triangle> Triangles(const TriMesh& mesh) {
  std::vector<Triangle> triangles;
  for (const auto fh : mesh.faces()) {
    Triangle t;
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) t[k++] = ToEigen(mesh.point(vh));
    triangles.push_back(t);
  }
  return triangles;
}

// Parity of the crossings of a ray from `p` (an irrational-ish direction, to miss edges).
bool Inside(const std::vector<Triangle>& triangles, const Eigen::Vector3d& p) {
  const Eigen::Vector3d dir = Eigen::Vector3d(0.5377, 0.8319, 0.1371).normalized();
  int crossings = 0;
  for (const auto& t : triangles) {
    const Eigen::Vector3d e1 = t[1] - t[0], e2 = t[2] - t[0];
    const Eigen::Vector3d h = dir.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-12) continue;
    const Eigen::Vector3d s = p - t[0];
    const double u = s.dot(h) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (e2.dot(q) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

class SampleBracketTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { mesh_ = new TriMesh(MakeSampleBracket()); }
  static void TearDownTestSuite() { delete mesh_; }
  static const TriMesh& Mesh() { return *mesh_; }

  // Regular grid points inside the part: a volume sample independent of the tessellation.
  static std::vector<Eigen::Vector3d> InteriorSamples(const std::vector<Triangle>& triangles) {
    std::vector<Eigen::Vector3d> samples;
    for (double x = -55; x <= 55; x += 5.0) {
      for (double y = -35; y <= 35; y += 5.0) {
        for (double z = -40; z <= 40; z += 5.0) {
          if (Inside(triangles, {x, y, z})) samples.emplace_back(x, y, z);
        }
      }
    }
    return samples;
  }

  static TriMesh* mesh_;
};
TriMesh* SampleBracketTest::mesh_ = nullptr;

TEST_F(SampleBracketTest, IsAClosedManifoldWithThreeThroughHoles) {
  const TriMesh& mesh = Mesh();
  for (const auto heh : mesh.halfedges()) ASSERT_FALSE(mesh.is_boundary(heh));
  for (const auto vh : mesh.vertices()) ASSERT_TRUE(mesh.is_manifold(vh));
  // Euler characteristic 2 - 2 g with genus g = 3 holes.
  const long euler = static_cast<long>(mesh.n_vertices()) - static_cast<long>(mesh.n_edges()) +
                     static_cast<long>(mesh.n_faces());
  EXPECT_EQ(euler, 2 - 2 * 3);
  EXPECT_LT(mesh.n_faces(), 5000u);
  EXPECT_GT(mesh.n_faces(), 500u);
}

TEST_F(SampleBracketTest, NormalsPointOutward) {
  const TriMesh& mesh = Mesh();
  const auto triangles = Triangles(mesh);
  double volume = 0.0;
  for (const auto& t : triangles) volume += t[0].dot(t[1].cross(t[2])) / 6.0;
  // Cells of the design minus three 16-gon holes: about 100 x 60 x 8 + 8 x 60 x 62 + gusset.
  EXPECT_GT(volume, 70000.0);
  EXPECT_LT(volume, 90000.0);
  // Just in front of every 7th face is outside, just behind it inside.
  int checked = 0;
  for (const auto fh : mesh.faces()) {
    if (fh.idx() % 7 != 0) continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto vh : mesh.fv_range(fh)) centroid += ToEigen(mesh.point(vh)) / 3.0;
    const Eigen::Vector3d normal = ToEigen(mesh.normal(fh));
    EXPECT_NEAR(normal.norm(), 1.0, 1e-9);
    EXPECT_FALSE(Inside(triangles, centroid + 0.01 * normal)) << "face " << fh.idx();
    EXPECT_TRUE(Inside(triangles, centroid - 0.01 * normal)) << "face " << fh.idx();
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST_F(SampleBracketTest, SizeColourAndOrigin) {
  const TriMesh& mesh = Mesh();
  std::vector<Eigen::Vector3d> points;
  for (const auto vh : mesh.vertices()) {
    points.push_back(ToEigen(mesh.point(vh)));
    ASSERT_EQ(mesh.color(vh), OpenMesh::Vec3uc(170, 170, 175));
  }
  const Sphere sphere = MinimalEnclosingSphere(points);
  EXPECT_GT(2 * sphere.radius_mm, 100.0);
  EXPECT_LT(2 * sphere.radius_mm, 140.0);
  EXPECT_LT(sphere.centre.norm(), 1.0);
}

TEST_F(SampleBracketTest, HasNoRotationalSymmetry) {
  const auto triangles = Triangles(Mesh());
  const auto samples = InteriorSamples(triangles);
  ASSERT_GT(samples.size(), 100u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : samples) mean += p / static_cast<double>(samples.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : samples) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d moments = solver.eigenvalues();  // ascending
  // Distinct second moments: no continuous symmetry, principal axes well defined.
  EXPECT_GT(moments[1], 1.1 * moments[0]);
  EXPECT_GT(moments[2], 1.1 * moments[1]);
  // A 180 deg turn about any principal axis (through the centroid) moves much of the volume
  // out of the part; a symmetric part would map onto itself.
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::AngleAxisd turn(std::numbers::pi, solver.eigenvectors().col(axis));
    int outside = 0;
    for (const auto& p : samples) {
      if (!Inside(triangles, mean + turn * (p - mean))) ++outside;
    }
    EXPECT_GT(outside, static_cast<int>(samples.size()) / 5) << "principal axis " << axis;
  }
}

TEST_F(SampleBracketTest, BundledFileMatchesGenerator) {
  const auto path = test::SourceDir() / "resources" / "sample" / "bracket.ply";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  EXPECT_LT(std::filesystem::file_size(path), 300u * 1024u);
  const Model model = LoadModel(path);
  const TriMesh& mesh = Mesh();
  EXPECT_EQ(model.mesh.n_vertices(), mesh.n_vertices());
  EXPECT_EQ(model.mesh.n_faces(), mesh.n_faces());
  EXPECT_TRUE(model.has_vertex_colors);
  EXPECT_TRUE(model.warnings.empty());
  std::vector<Eigen::Vector3d> points;
  for (const auto vh : mesh.vertices()) points.push_back(ToEigen(mesh.point(vh)));
  const Sphere expected = MinimalEnclosingSphere(points);
  EXPECT_NEAR(model.sphere.radius_mm, expected.radius_mm, 1e-3);
  EXPECT_THAT(model.sphere.centre, test::MatrixNear(expected.centre, 1e-3));
}

}  // namespace
}  // namespace layermod
