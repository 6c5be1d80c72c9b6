// SPDX-License-Identifier: MIT
#include "geometry/convex_hull.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>

#include "support/matchers.h"
#include "util/error.h"

namespace layermod {
namespace {

using test::MatrixNear;

std::vector<Eigen::Vector3d> BoxCorners(const Eigen::Vector3d& size) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back(i & 1 ? size.x() : 0.0, i & 2 ? size.y() : 0.0, i & 4 ? size.z() : 0.0);
  }
  return corners;
}

// A closed, convex, outward-wound triangle mesh that contains every point.
void ExpectValidHull(const ConvexHull& hull, const std::vector<Eigen::Vector3d>& points,
                     double tolerance) {
  std::map<std::pair<int, int>, int> directed_edges;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : hull.vertices) centroid += v;
  centroid /= static_cast<double>(hull.vertices.size());
  for (const auto& t : hull.triangles) {
    for (int i = 0; i < 3; ++i) ++directed_edges[{t[i], t[(i + 1) % 3]}];
    const Eigen::Vector3d& a = hull.vertices[t[0]];
    const Eigen::Vector3d normal =
        (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a).normalized();
    EXPECT_GT(normal.dot(a - centroid), 0.0) << "a triangle faces inwards";
    double highest = -std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& p : points) highest = std::max(highest, normal.dot(p - a));
    EXPECT_LE(highest, tolerance) << "a point lies outside the hull";
  }
  for (const auto& [edge, count] : directed_edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed_edges.count({edge.second, edge.first}), 1u) << "the hull has a border";
  }
  // Euler: V - E + F = 2 for a closed surface of genus 0.
  const auto edges = static_cast<long>(directed_edges.size() / 2);
  EXPECT_EQ(
      static_cast<long>(hull.vertices.size()) - edges + static_cast<long>(hull.triangles.size()),
      2);
}

TEST(ConvexHullTest, CubeWithFaceCentresAndRepeatedCornersKeepsOnlyTheCorners) {
  std::vector<Eigen::Vector3d> points = BoxCorners({10, 10, 10});
  for (int axis = 0; axis < 3; ++axis) {
    for (double side : {0.0, 10.0}) {
      Eigen::Vector3d centre(5, 5, 5);
      centre[axis] = side;
      points.push_back(centre);
    }
  }
  points.emplace_back(5, 5, 5);  // inside
  points.emplace_back(5, 0, 0);  // on an edge
  const std::size_t distinct = points.size();
  for (std::size_t i = 0; i < distinct; ++i) points.push_back(points[i]);  // every point twice
  const ConvexHull hull = ComputeConvexHull(points);
  EXPECT_EQ(hull.vertices.size(), 8u);
  EXPECT_EQ(hull.triangles.size(), 12u);
  ExpectValidHull(hull, points, 1e-9);
}

TEST(ConvexHullTest, PointsOnASphereAreAllHullVertices) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 2000; ++i) {
    points.push_back(50.0 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
  }
  const ConvexHull hull = ComputeConvexHull(points);
  EXPECT_EQ(hull.vertices.size(), points.size());
  ExpectValidHull(hull, points, 1e-7);
}

TEST(ConvexHullTest, ACloudOfPointsIsContained) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-30.0, 30.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 5000; ++i) {
    // Coarse coordinates: many points share planes and lines.
    points.emplace_back(std::round(coordinate(rng)), std::round(coordinate(rng)),
                        std::round(coordinate(rng) / 3.0));
  }
  const ConvexHull hull = ComputeConvexHull(points);
  ASSERT_FALSE(hull.Empty());
  ExpectValidHull(hull, points, 1e-9);
}

TEST(ConvexHullTest, PointsWithoutVolumeGiveAnEmptyHull) {
  EXPECT_TRUE(ComputeConvexHull({}).Empty());
  EXPECT_TRUE(ComputeConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).Empty());
  EXPECT_TRUE(ComputeConvexHull({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}}).Empty());
  EXPECT_TRUE(ComputeConvexHull({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}}).Empty());
  std::vector<Eigen::Vector3d> flat;
  for (int i = 0; i < 50; ++i) flat.emplace_back(i % 7, i / 7, 2.0);
  EXPECT_TRUE(ComputeConvexHull(flat).Empty());
}

TEST(ConvexHullTest, RejectsNonFinitePoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ComputeConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}), Error);
}

TEST(ConvexHullTest, VolumeCentroidOfABoxAndATetrahedron) {
  const ConvexHull box = ComputeConvexHull(BoxCorners({100, 60, 20}));
  EXPECT_THAT(HullVolumeCentroid(box), MatrixNear(Eigen::Vector3d(50, 30, 10), 1e-9));
  // A square pyramid: the centroid is a quarter of the way up, the mean of its corners a fifth.
  const std::vector<Eigen::Vector3d> pyramid = {
      {0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}, {5, 5, 12}};
  EXPECT_THAT(HullVolumeCentroid(ComputeConvexHull(pyramid)),
              MatrixNear(Eigen::Vector3d(5, 5, 3), 1e-9));
  EXPECT_THROW(HullVolumeCentroid(ConvexHull{}), Error);
}

}  // namespace
}  // namespace layermod
