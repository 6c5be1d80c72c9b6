// SPDX-License-Identifier: MIT
#include "eval/point_search.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "util/error.h"

namespace layermod {
namespace {

double BruteForceNearest(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& q) {
  double best = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : points) best = std::min(best, (p - q).norm());
  return best;
}

TEST(PointKdTreeTest, RefusesAnEmptySet) { EXPECT_THROW(PointKdTree({}), Error); }

TEST(PointKdTreeTest, SinglePointIsAlwaysTheNearest) {
  const PointKdTree tree({Eigen::Vector3d(1.0, 2.0, 3.0)});
  EXPECT_DOUBLE_EQ(tree.NearestDistance({1.0, 2.0, 7.0}), 4.0);
}

TEST(PointKdTreeTest, AgreesWithBruteForceOnRandomClouds) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
  std::vector<Eigen::Vector3d> points(2000);
  for (Eigen::Vector3d& p : points) p = {coordinate(rng), coordinate(rng), 0.1 * coordinate(rng)};
  points.push_back(points[5]);  // duplicates must not confuse the splits
  const PointKdTree tree(points);
  EXPECT_EQ(tree.size(), points.size());
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d q(1.5 * coordinate(rng), 1.5 * coordinate(rng), coordinate(rng));
    EXPECT_DOUBLE_EQ(tree.NearestDistance(q), BruteForceNearest(points, q));
  }
}

TEST(PointKdTreeTest, StoredPointsAreAtDistanceZero) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(i, (i * 7) % 13, (i * 3) % 5);
  const PointKdTree tree(points);
  for (const Eigen::Vector3d& p : points) EXPECT_EQ(tree.NearestDistance(p), 0.0);
}

}  // namespace
}  // namespace layermod
