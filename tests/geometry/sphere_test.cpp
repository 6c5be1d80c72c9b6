// SPDX-License-Identifier: MIT
#include "geometry/sphere.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>

#include "support/matchers.h"
#include "util/error.h"

namespace layermod {
namespace {

using Points = std::vector<Eigen::Vector3d>;
using test::MatrixNear;

// Smallest sphere through `support` with its centre in their affine hull; nullopt when the
// support is affinely dependent.
std::optional<Sphere> Circumsphere(const Points& support) {
  const Eigen::Vector3d& origin = support.front();
  const int m = static_cast<int>(support.size()) - 1;
  if (m == 0) return Sphere{origin, 0.0};
  Eigen::MatrixXd edges(3, m);
  Eigen::VectorXd rhs(m);
  for (int i = 0; i < m; ++i) {
    edges.col(i) = support[i + 1] - origin;
    rhs[i] = 0.5 * edges.col(i).squaredNorm();
  }
  const Eigen::MatrixXd gram = edges.transpose() * edges;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(gram);
  lu.setThreshold(1e-10);
  if (lu.rank() < m) return std::nullopt;
  const Eigen::Vector3d offset = edges * lu.solve(rhs);
  return Sphere{origin + offset, offset.norm()};
}

// The smallest of the spheres through 1..4 of the points that contains all of them.
Sphere BruteForceSphere(const Points& points) {
  const int n = static_cast<int>(points.size());
  Sphere best{Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()};
  auto consider = [&](const Points& support) {
    const auto sphere = Circumsphere(support);
    if (!sphere || sphere->radius_mm >= best.radius_mm) return;
    for (const auto& p : points) {
      if ((p - sphere->centre).norm() > sphere->radius_mm * (1.0 + 1e-9) + 1e-12) return;
    }
    best = *sphere;
  };
  for (int a = 0; a < n; ++a) {
    consider({points[a]});
    for (int b = a + 1; b < n; ++b) {
      consider({points[a], points[b]});
      for (int c = b + 1; c < n; ++c) {
        consider({points[a], points[b], points[c]});
        for (int d = c + 1; d < n; ++d) consider({points[a], points[b], points[c], points[d]});
      }
    }
  }
  return best;
}

void ExpectContainsAll(const Sphere& sphere, const Points& points, double relative_tol) {
  for (const auto& p : points) {
    ASSERT_LE((p - sphere.centre).norm(), sphere.radius_mm * (1.0 + relative_tol) + 1e-12);
  }
}

// Random point sets of several kinds, including the degenerate ones Welzl's textbook version
// assumes away: duplicates, coplanar, collinear and co-spherical (grid) points.
Points RandomSet(std::mt19937_64& rng, int kind) {
  std::uniform_int_distribution<int> count_dist(5, 12);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  std::uniform_int_distribution<int> grid(-2, 2);
  std::normal_distribution<double> normal;
  const int n = count_dist(rng);
  Points points;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
    switch (kind) {
      case 1:  // on a sphere
        p = 7.0 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
        break;
      case 2:  // coplanar
        p.z() = 0.5 * p.x() - 0.25 * p.y();
        break;
      case 3:  // collinear
        p = Eigen::Vector3d(1, 2, 3) + coord(rng) * Eigen::Vector3d(0.3, -0.5, 0.8);
        break;
      case 4:  // small integer grid: many co-spherical subsets and duplicates
        p = Eigen::Vector3d(grid(rng), grid(rng), grid(rng));
        break;
      case 5:  // duplicates of earlier points
        if (i > 0 && i % 2 == 0) p = points[i / 2];
        break;
      default:
        break;
    }
    points.push_back(p);
  }
  return points;
}

TEST(MinimalEnclosingSphereTest, MatchesBruteForceOnRandomAndDegenerateSets) {
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 600; ++trial) {
    const Points points = RandomSet(rng, trial % 6);
    const Sphere expected = BruteForceSphere(points);
    const Sphere actual = MinimalEnclosingSphere(points);
    ASSERT_NEAR(actual.radius_mm, expected.radius_mm, 1e-9 * (1.0 + expected.radius_mm))
        << "trial " << trial << " kind " << trial % 6;
    ASSERT_THAT(actual.centre, MatrixNear(expected.centre, 1e-6)) << "trial " << trial;
    ExpectContainsAll(actual, points, 1e-12);
  }
}

TEST(MinimalEnclosingSphereTest, CubeCornersGiveHalfDiagonal) {
  Points corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back(i & 1 ? 30.0 : 10.0, i & 2 ? 5.0 : -15.0, i & 4 ? 2.0 : -18.0);
  }
  const Sphere sphere = MinimalEnclosingSphere(corners);
  EXPECT_NEAR(sphere.radius_mm, 0.5 * std::sqrt(3.0) * 20.0, 1e-9);
  EXPECT_THAT(sphere.centre, MatrixNear(Eigen::Vector3d(20, -5, -8), 1e-9));
}

TEST(MinimalEnclosingSphereTest, PointsOnASphereGiveThatSphere) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  const Eigen::Vector3d centre(100, -40, 250);
  Points points;
  for (int i = 0; i < 2000; ++i) {
    points.push_back(centre +
                     55.0 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized());
  }
  const Sphere sphere = MinimalEnclosingSphere(points);
  EXPECT_NEAR(sphere.radius_mm, 55.0, 1e-7);
  EXPECT_THAT(sphere.centre, MatrixNear(centre, 1e-6));
}

TEST(MinimalEnclosingSphereTest, ManyDegenerateSupportsOnCircleAndGrid) {
  // Thousands of co-circular points: every 4-subset is coplanar and co-circular.
  Points circle;
  for (int i = 0; i < 5000; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / 5000.0;
    circle.emplace_back(3.0 + 12.0 * std::cos(angle), -1.0, 12.0 * std::sin(angle));
  }
  const Sphere on_circle = MinimalEnclosingSphere(circle);
  EXPECT_NEAR(on_circle.radius_mm, 12.0, 1e-9);
  EXPECT_THAT(on_circle.centre, MatrixNear(Eigen::Vector3d(3, -1, 0), 1e-9));

  // A regular grid: 8 co-spherical corners and masses of coplanar, collinear points.
  Points grid;
  for (int x = 0; x <= 20; ++x) {
    for (int y = 0; y <= 20; ++y) {
      for (int z = 0; z <= 10; ++z) grid.emplace_back(x, y, z);
    }
  }
  const Sphere on_grid = MinimalEnclosingSphere(grid);
  EXPECT_NEAR(on_grid.radius_mm, 0.5 * std::sqrt(20.0 * 20.0 * 2 + 10.0 * 10.0), 1e-9);
  EXPECT_THAT(on_grid.centre, MatrixNear(Eigen::Vector3d(10, 10, 5), 1e-9));
}

TEST(MinimalEnclosingSphereTest, RegularTetrahedron) {
  const Points points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {0.2, 0.1, -0.3}};
  const Sphere sphere = MinimalEnclosingSphere(points);
  EXPECT_NEAR(sphere.radius_mm, std::sqrt(3.0), 1e-12);
  EXPECT_THAT(sphere.centre, MatrixNear(Eigen::Vector3d::Zero(), 1e-12));
}

TEST(MinimalEnclosingSphereTest, TwoPointsAndOnePoint) {
  const Sphere two = MinimalEnclosingSphere({{0, 0, 0}, {6, 8, 0}});
  EXPECT_NEAR(two.radius_mm, 5.0, 1e-12);
  EXPECT_THAT(two.centre, MatrixNear(Eigen::Vector3d(3, 4, 0), 1e-12));

  const Sphere one = MinimalEnclosingSphere({{1.5, -2, 3}});
  EXPECT_EQ(one.radius_mm, 0.0);
  EXPECT_THAT(one.centre, MatrixNear(Eigen::Vector3d(1.5, -2, 3), 0.0));

  const Sphere repeated = MinimalEnclosingSphere(Points(10, Eigen::Vector3d(4, 4, 4)));
  EXPECT_EQ(repeated.radius_mm, 0.0);
}

TEST(MinimalEnclosingSphereTest, FarFromOriginKeepsPrecision) {
  const Eigen::Vector3d offset(1e6, -2e6, 5e5);
  Points points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (auto& p : points) p += offset;
  const Sphere sphere = MinimalEnclosingSphere(points);
  EXPECT_NEAR(sphere.radius_mm, std::sqrt(3.0), 1e-8);
  EXPECT_THAT(sphere.centre, MatrixNear(offset, 1e-8));
}

TEST(MinimalEnclosingSphereTest, LargeCloudIsContainedAndTouchesBoundary) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  Points points;
  while (points.size() < 50000) {
    const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
    // An ellipsoid-like, off-centre cloud: the sphere is decided by a few far points.
    if (p.squaredNorm() <= 1.0)
      points.push_back(Eigen::Vector3d(80 * p.x() + 5, 40 * p.y(), 20 * p.z()));
  }
  const Sphere sphere = MinimalEnclosingSphere(points);
  ExpectContainsAll(sphere, points, 1e-6);
  int on_boundary = 0;
  for (const auto& p : points) {
    if (std::abs((p - sphere.centre).norm() - sphere.radius_mm) <= 1e-9 * sphere.radius_mm)
      ++on_boundary;
  }
  EXPECT_GE(on_boundary, 2);
  EXPECT_LE(sphere.radius_mm, 80.0);
  EXPECT_GT(sphere.radius_mm, 79.0);

  // Deterministic and independent of the input order.
  const Sphere again = MinimalEnclosingSphere(points);
  EXPECT_EQ(again.radius_mm, sphere.radius_mm);
  std::reverse(points.begin(), points.end());
  EXPECT_NEAR(MinimalEnclosingSphere(points).radius_mm, sphere.radius_mm, 1e-9 * sphere.radius_mm);
}

TEST(MinimalEnclosingSphereTest, RejectsEmptyAndNonFiniteInput) {
  EXPECT_THROW(MinimalEnclosingSphere({}), Error);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(MinimalEnclosingSphere({{0, 0, 0}, {1, nan, 0}}), Error);
  EXPECT_THROW(MinimalEnclosingSphere({{0, 0, inf}, {1, 0, 0}}), Error);
}

}  // namespace
}  // namespace layermod
