// SPDX-License-Identifier: MIT
#include "eval/point_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "util/error.h"

namespace layermod {
namespace {

constexpr std::uint32_t kLeafSize = 8;

int WidestAxis(const std::vector<Eigen::Vector3d>& points, std::uint32_t begin, std::uint32_t end) {
  Eigen::Vector3d lo = points[begin];
  Eigen::Vector3d hi = points[begin];
  for (std::uint32_t i = begin + 1; i < end; ++i) {
    lo = lo.cwiseMin(points[i]);
    hi = hi.cwiseMax(points[i]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  return axis;
}

}  // namespace

PointKdTree::PointKdTree(std::vector<Eigen::Vector3d> points) : points_(std::move(points)) {
  if (points_.empty()) throw Error("nearest-point search needs at least one point");
  nodes_.reserve(2 * points_.size() / kLeafSize + 1);
  Build(0, static_cast<std::uint32_t>(points_.size()));
}

std::int32_t PointKdTree::Build(std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::int32_t>(nodes_.size());
  nodes_.push_back(Node{begin, end});
  if (end - begin <= kLeafSize) return index;
  const int axis = WidestAxis(points_, begin, end);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(
      points_.begin() + begin, points_.begin() + middle, points_.begin() + end,
      [axis](const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a[axis] < b[axis]; });
  const double split = points_[middle][axis];  // before the right subtree reorders its points
  const std::int32_t left = Build(begin, middle);
  const std::int32_t right = Build(middle, end);
  Node& node = nodes_[index];  // re-fetched: the recursion grew the vector
  node.axis = axis;
  node.split = split;
  node.left = left;
  node.right = right;
  return index;
}

void PointKdTree::Search(std::int32_t node_index, const Eigen::Vector3d& query,
                         double& best_sq) const {
  const Node& node = nodes_[node_index];
  if (node.axis < 0) {
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      best_sq = std::min(best_sq, (points_[i] - query).squaredNorm());
    }
    return;
  }
  // Points of the left subtree have coordinate <= split, of the right one >= split.
  const double offset = query[node.axis] - node.split;
  const std::int32_t near = offset < 0.0 ? node.left : node.right;
  const std::int32_t far = offset < 0.0 ? node.right : node.left;
  Search(near, query, best_sq);
  if (offset * offset < best_sq) Search(far, query, best_sq);
}

double PointKdTree::NearestDistance(const Eigen::Vector3d& query) const {
  double best_sq = std::numeric_limits<double>::infinity();
  Search(0, query, best_sq);
  return std::sqrt(best_sq);
}

}  // namespace layermod
