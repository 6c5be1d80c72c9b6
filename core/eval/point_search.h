// SPDX-License-Identifier: MIT
#pragma once

// Exact nearest-neighbour search over a fixed 3D point set (ADD-S, Eq. 7 of the paper, asks for
// the closest model point to each transformed model point: thousands of queries per pose).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace layermod {

// A static k-d tree (median splits, leaves of a few points). Queries are exact.
class PointKdTree {
 public:
  // Throws Error for an empty point set.
  explicit PointKdTree(std::vector<Eigen::Vector3d> points);

  // Distance from `query` to the nearest stored point.
  double NearestDistance(const Eigen::Vector3d& query) const;

  std::size_t size() const { return points_.size(); }

 private:
  struct Node {
    std::uint32_t begin = 0;  // points_[begin, end) belong to this subtree
    std::uint32_t end = 0;
    std::int32_t axis = -1;  // -1: leaf
    double split = 0.0;
    std::int32_t left = -1;
    std::int32_t right = -1;
  };

  std::int32_t Build(std::uint32_t begin, std::uint32_t end);
  void Search(std::int32_t node, const Eigen::Vector3d& query, double& best_sq) const;

  std::vector<Eigen::Vector3d> points_;  // reordered so every subtree is a contiguous range
  std::vector<Node> nodes_;
};

}  // namespace layermod
