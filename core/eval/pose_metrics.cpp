// SPDX-License-Identifier: MIT
#include "eval/pose_metrics.h"

#include <cmath>
#include <limits>

#include "util/error.h"

namespace layermod {
namespace {

void CheckPoints(const std::vector<Eigen::Vector3d>& model_points) {
  if (model_points.empty()) throw Error("pose error needs at least one model point");
}

bool InFront(const Eigen::Vector3d& point_in_cam) { return point_in_cam.z() > 0.0; }

}  // namespace

double AddErrorMm(const std::vector<Eigen::Vector3d>& model_points, const Pose& estimated,
                  const Pose& truth) {
  CheckPoints(model_points);
  double sum = 0.0;
  for (const Eigen::Vector3d& x : model_points) sum += (estimated * x - truth * x).norm();
  return sum / static_cast<double>(model_points.size());
}

double AddSErrorMm(const std::vector<Eigen::Vector3d>& model_points, const PointKdTree& model_tree,
                   const Pose& estimated, const Pose& truth) {
  CheckPoints(model_points);
  // Rigid motions keep distances, so the nearest estimated point to truth * x is the nearest
  // model point to estimated^-1 * truth * x.
  const Pose estimate_from_truth = estimated.Inverse() * truth;
  double sum = 0.0;
  for (const Eigen::Vector3d& x : model_points) {
    sum += model_tree.NearestDistance(estimate_from_truth * x);
  }
  return sum / static_cast<double>(model_points.size());
}

double Projection2DErrorPx(const std::vector<Eigen::Vector3d>& model_points, const Pose& estimated,
                           const Pose& truth, const PinholeCamera& camera) {
  CheckPoints(model_points);
  double sum = 0.0;
  for (const Eigen::Vector3d& x : model_points) {
    const Eigen::Vector3d a = estimated * x;
    const Eigen::Vector3d b = truth * x;
    if (!InFront(a) || !InFront(b)) return std::numeric_limits<double>::infinity();
    sum += (camera.Project(a) - camera.Project(b)).norm();
  }
  return sum / static_cast<double>(model_points.size());
}

cv::Rect ProjectedBox(const std::vector<Eigen::Vector3d>& model_points, const Pose& pose,
                      const PinholeCamera& camera) {
  CheckPoints(model_points);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Eigen::Vector3d& x : model_points) {
    const Eigen::Vector3d point_in_cam = pose * x;
    if (!InFront(point_in_cam)) return {};
    const Eigen::Vector2d pixel = camera.Project(point_in_cam);
    lo = lo.cwiseMin(pixel);
    hi = hi.cwiseMax(pixel);
  }
  const int x0 = static_cast<int>(std::floor(lo.x()));
  const int y0 = static_cast<int>(std::floor(lo.y()));
  return {x0, y0, static_cast<int>(std::ceil(hi.x())) - x0,
          static_cast<int>(std::ceil(hi.y())) - y0};
}

double BoxIoU(const cv::Rect& a, const cv::Rect& b) {
  const double intersection = (a & b).area();
  const double union_area = static_cast<double>(a.area()) + b.area() - intersection;
  return union_area > 0.0 ? intersection / union_area : 0.0;
}

}  // namespace layermod
