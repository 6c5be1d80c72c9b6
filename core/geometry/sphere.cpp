// SPDX-License-Identifier: MIT
#include "geometry/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <list>
#include <random>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

// A support point whose distance from the affine hull of the current support is below this
// fraction of the working scale is treated as lying in that hull (degenerate support): solving
// for a sphere through it would be ill-conditioned and, in exact arithmetic, never needed.
constexpr double kAffineEps = 1e-10;
// Relative slack on the squared radius so that boundary points do not re-enter the recursion
// because of rounding.
constexpr double kExcessEps = 1e-12;
constexpr int kMaxPivotRounds = 10000;
constexpr std::uint64_t kShuffleSeed = 0x4c617965724d4f44ULL;  // fixed: results are reproducible

using PointList = std::list<Eigen::Vector3d>;
using PointIt = PointList::iterator;

// Welzl's move-to-front recursion with Gärtner's pivoting. The support (at most 4 points on the
// boundary of the current ball) is kept with an orthonormal basis of its affine hull, so that
// pushing a point costs O(1) and degenerate supports are detected and refused.
class MinisphereSolver {
 public:
  explicit MinisphereSolver(PointList points, double scale)
      : points_(std::move(points)), scale_sqr_(scale * scale) {}

  Sphere Solve() {
    PointIt prefix_end = std::next(points_.begin());
    MoveToFront(prefix_end);
    for (int round = 0; round < kMaxPivotRounds; ++round) {
      const PointIt pivot = FarthestOutside();
      if (pivot == points_.end()) break;
      const double old_radius_sqr = radius_sqr_;
      if (prefix_end == pivot) ++prefix_end;
      if (Push(*pivot)) {
        MoveToFront(prefix_end);
        Pop();
        points_.splice(points_.begin(), points_, pivot);
      }
      // Without strict growth the pivot could only come from rounding; the final containment
      // pass covers it.
      if (!(radius_sqr_ > old_radius_sqr)) break;
    }
    return {centre_, std::sqrt(std::max(radius_sqr_, 0.0))};
  }

 private:
  double Excess(const Eigen::Vector3d& p) const {
    return (p - centre_).squaredNorm() - radius_sqr_ * (1.0 + kExcessEps);
  }

  // Makes the current ball the smallest ball of [begin, end) with the support on its boundary.
  void MoveToFront(PointIt end) {
    if (size_ == 4) return;
    for (PointIt it = points_.begin(); it != end;) {
      const PointIt current = it++;
      if (Excess(*current) <= 0.0 || !Push(*current)) continue;
      MoveToFront(current);
      Pop();
      points_.splice(points_.begin(), points_, current);
    }
  }

  PointIt FarthestOutside() {
    PointIt best = points_.end();
    double best_excess = 0.0;
    for (PointIt it = points_.begin(); it != points_.end(); ++it) {
      const double excess = Excess(*it);
      if (excess > best_excess) {
        best_excess = excess;
        best = it;
      }
    }
    return best;
  }

  // Adds `p` to the support and updates the ball to the smallest one through the support.
  // Returns false (support unchanged) when `p` lies in the affine hull of the support.
  bool Push(const Eigen::Vector3d& p) {
    if (size_ == 0) {
      origin_ = p;
      centre_ = p;
      radius_sqr_ = 0.0;
      size_ = 1;
      return true;
    }
    if (size_ == 4) return false;
    const int column = size_ - 1;  // index of the new basis vector
    const Eigen::Vector3d d = p - origin_;
    Eigen::Vector3d residual = d;
    for (int j = 0; j < column; ++j) {
      coords_(j, column) = basis_.col(j).dot(d);
      residual -= coords_(j, column) * basis_.col(j);
    }
    const double height = residual.norm();
    if (height <= kAffineEps * std::sqrt(std::max(scale_sqr_, d.squaredNorm()))) return false;
    basis_.col(column) = residual / height;
    coords_(column, column) = height;
    half_sqr_len_[column] = 0.5 * d.squaredNorm();
    ++size_;
    UpdateBall();
    return true;
  }

  // The current ball stays: it is the result of the recursion that pushed the point.
  void Pop() { --size_; }

  // Centre c = origin + Q mu with 2 (s_i - origin) . (c - origin) = |s_i - origin|^2 for every
  // support point: with s_i - origin = Q r_i this is the triangular system R^T mu = h.
  void UpdateBall() {
    const int m = size_ - 1;
    Eigen::Vector3d mu = Eigen::Vector3d::Zero();
    for (int i = 0; i < m; ++i) {
      double sum = half_sqr_len_[i];
      for (int j = 0; j < i; ++j) sum -= coords_(j, i) * mu[j];
      mu[i] = sum / coords_(i, i);
    }
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (int j = 0; j < m; ++j) offset += mu[j] * basis_.col(j);
    centre_ = origin_ + offset;
    radius_sqr_ = offset.squaredNorm();
  }

  PointList points_;
  double scale_sqr_;
  int size_ = 0;                                      // number of support points
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // first support point
  Eigen::Matrix3d basis_ = Eigen::Matrix3d::Zero();   // orthonormal basis of the affine hull
  Eigen::Matrix3d coords_ = Eigen::Matrix3d::Zero();  // column i: s_{i+1} - origin in the basis
  std::array<double, 3> half_sqr_len_{};
  Eigen::Vector3d centre_ = Eigen::Vector3d::Zero();  // current ball
  double radius_sqr_ = -1.0;                          // negative: no ball yet
};

void CheckPoints(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) throw Error("minimal enclosing sphere: no points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      throw Error("minimal enclosing sphere: point " + std::to_string(i) +
                  " has a non-finite coordinate");
    }
  }
}

// Deterministic Fisher-Yates: std::shuffle's sequence depends on the standard library, and the
// expected linear time of move-to-front needs a random order (input files are often sorted).
PointList ShuffledRelative(const std::vector<Eigen::Vector3d>& points,
                           const Eigen::Vector3d& origin) {
  std::vector<Eigen::Vector3d> shuffled;
  shuffled.reserve(points.size());
  for (const auto& p : points) shuffled.push_back(p - origin);
  std::mt19937_64 rng(kShuffleSeed);
  for (std::size_t i = shuffled.size(); i > 1; --i) {
    std::swap(shuffled[i - 1], shuffled[rng() % i]);
  }
  return PointList(shuffled.begin(), shuffled.end());
}

}  // namespace

Sphere MinimalEnclosingSphere(const std::vector<Eigen::Vector3d>& points) {
  CheckPoints(points);
  // Work relative to the bounding-box centre: far-from-origin models keep their precision.
  Eigen::Vector3d lo = points.front();
  Eigen::Vector3d hi = points.front();
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  const double scale = 0.5 * (hi - lo).norm();
  Sphere sphere = MinisphereSolver(ShuffledRelative(points, mid), scale).Solve();
  // Rounding may leave a point a hair outside; the ball must contain every point.
  double max_sqr = 0.0;
  for (const auto& p : points) max_sqr = std::max(max_sqr, (p - mid - sphere.centre).squaredNorm());
  sphere.radius_mm = std::max(sphere.radius_mm, std::sqrt(max_sqr));
  sphere.centre += mid;
  return sphere;
}

}  // namespace layermod
