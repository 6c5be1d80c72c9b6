// SPDX-License-Identifier: MIT
#include "pose/icp.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "render/rasterizer.h"
#include "util/error.h"

namespace layermod {
namespace {

struct SurfaceSample {
  Eigen::Vector3d point_in_model;
  Eigen::Vector3d normal_in_model;
};

// Visible surface of the model at `pose`, sampled on a pixel grid of its render.
std::vector<SurfaceSample> SampleVisibleSurface(const RenderMesh& mesh, const PinholeCamera& camera,
                                                const Pose& pose, int step_px) {
  // Only every step_px-th pixel is read, so only those are rendered: pixel (x, y) of the sparse
  // render is pixel (step_px * x, step_px * y) of the camera.
  const RenderedView view = RenderView(mesh, camera.EveryNthPixel(step_px), pose);
  std::vector<SurfaceSample> samples;
  if (view.empty()) return samples;
  const Pose model_from_cam = pose.Inverse();
  for (int y = 0; y < view.depth_mm.rows; ++y) {
    for (int x = 0; x < view.depth_mm.cols; ++x) {
      const float depth = view.depth_mm.at<float>(y, x);
      if (depth <= 0.0f) continue;
      const cv::Vec3f normal = view.normals.at<cv::Vec3f>(y, x);
      const Eigen::Vector2d pixel(step_px * (x + view.roi.x), step_px * (y + view.roi.y));
      const Eigen::Vector3d point_in_cam = camera.Backproject(pixel, static_cast<double>(depth));
      samples.push_back({model_from_cam * point_in_cam,
                         model_from_cam.R * Eigen::Vector3d(normal[0], normal[1], normal[2])});
    }
  }
  return samples;
}

// std::lround for pixel coordinates without the library call (it ran twice per sample in every
// ICP step): the truncation and the remainder are exact, and so is comparing it with one half.
// Coordinates beyond +-2^30 (or NaN) come back as -1, outside every image.
int RoundToPixel(double x) {
  constexpr double kLimit = 1 << 30;
  if (!(std::abs(x) < kLimit)) return -1;
  const auto truncated = static_cast<int>(x);
  const double rest = x - truncated;
  return truncated + (rest >= 0.5 ? 1 : 0) - (rest <= -0.5 ? 1 : 0);
}

// Scene point seen at the pixel where `point_in_cam` projects; false when none.
bool SceneCorrespondence(const PinholeCamera& camera, const cv::Mat& depth_mm,
                         const Eigen::Vector3d& point_in_cam, Eigen::Vector3d& scene_point) {
  if (point_in_cam.z() <= 0.0) return false;
  const Eigen::Vector2d pixel = camera.Project(point_in_cam);
  const int u = RoundToPixel(pixel.x());
  const int v = RoundToPixel(pixel.y());
  if (u < 0 || v < 0 || u >= depth_mm.cols || v >= depth_mm.rows) return false;
  const float depth = depth_mm.at<float>(v, u);
  if (depth <= 0.0f) return false;
  scene_point = camera.Backproject(Eigen::Vector2d(u, v), depth);
  return true;
}

struct StepResult {
  Eigen::Matrix<double, 6, 1> update = Eigen::Matrix<double, 6, 1>::Zero();
  double squared_error = 0.0;
  int inliers = 0;
};

// One Gauss-Newton step of point-to-plane alignment (model normals, small-angle linearisation),
// the rotation taken about `pivot` (the model's centre at `pose`). About the camera's origin a
// small rotation would also move the part by its distance times the angle (12 mm per degree at
// 700 mm): rotation and translation would be nearly interchangeable unknowns, and the step
// limits (max_step_deg, max_step_mm) would let a step move the part far more than they say.
StepResult SolveStep(const std::vector<SurfaceSample>& samples, const Pose& pose,
                     const PinholeCamera& camera, const cv::Mat& depth_mm, double gate_mm,
                     double huber_mm, const Eigen::Vector3d& pivot) {
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  StepResult result;
  for (const SurfaceSample& sample : samples) {
    const Eigen::Vector3d point = pose * sample.point_in_model;
    Eigen::Vector3d scene;
    if (!SceneCorrespondence(camera, depth_mm, point, scene)) continue;
    if ((point - scene).norm() > gate_mm) continue;
    const Eigen::Vector3d normal = pose.R * sample.normal_in_model;
    const double residual = normal.dot(point - scene);
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << (point - pivot).cross(normal), normal;
    const double weight = std::abs(residual) <= huber_mm ? 1.0 : huber_mm / std::abs(residual);
    const Eigen::Matrix<double, 6, 1> weighted = weight * jacobian;
    // The lower triangle only: the LDLT solve below reads no other entry.
    for (int col = 0; col < 6; ++col) {
      for (int row = col; row < 6; ++row) normal_matrix(row, col) += weighted(row) * jacobian(col);
    }
    rhs -= weighted * residual;
    result.squared_error += residual * residual;
    ++result.inliers;
  }
  if (result.inliers >= 6) {
    // Marquardt damping (scaled per parameter: rotations and translations differ in scale)
    // keeps directions the data barely constrains (sliding on a plane) from huge steps.
    normal_matrix.diagonal() *= 1.0 + 1e-2;
    result.update = normal_matrix.ldlt().solve(rhs);
    if (!result.update.allFinite()) result.update.setZero();
  }
  return result;
}

// Scales an update down so it rotates by at most max_step_deg and translates by at most
// max_step_mm.
Eigen::Matrix<double, 6, 1> ClampStep(const Eigen::Matrix<double, 6, 1>& update,
                                      const IcpOptions& options) {
  const double rotation_deg = RadToDeg(update.head<3>().norm());
  const double translation_mm = update.tail<3>().norm();
  const double factor = std::min({1.0, options.max_step_deg / std::max(rotation_deg, 1e-12),
                                  options.max_step_mm / std::max(translation_mm, 1e-12)});
  return update * factor;
}

// Point-to-plane steps with projective association shrink slowly along directions the data
// barely constrains (a flat part turning in its plane): successive steps then point the same
// way. As in Besl and McKay's accelerated ICP, such a step carries on part of the last one.
constexpr double kMomentum = 0.9;
constexpr double kSameDirectionCosine = 0.8;
// Rotations and translations of an update compare as the motion of a point this far from the
// rotation axis (the convergence test and the direction test).
constexpr double kRotationArmMm = 100.0;

// Whether `update` keeps the direction of `previous`.
bool KeepsDirection(const Eigen::Matrix<double, 6, 1>& update,
                    const Eigen::Matrix<double, 6, 1>& previous) {
  Eigen::Matrix<double, 6, 1> a = update;
  Eigen::Matrix<double, 6, 1> b = previous;
  a.head<3>() *= kRotationArmMm;
  b.head<3>() *= kRotationArmMm;
  const double norms = a.norm() * b.norm();
  return norms > 0.0 && a.dot(b) >= kSameDirectionCosine * norms;
}

Eigen::Vector3d MeanPosition(const RenderMesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3f& position : mesh.positions) sum += position.cast<double>();
  return mesh.positions.empty() ? sum
                                : Eigen::Vector3d(sum / static_cast<double>(mesh.positions.size()));
}

// Whether `pose` wandered too far from `start` (translation of the model centre, rotation).
bool Drifted(const Pose& start, const Pose& pose, const Eigen::Vector3d& centre,
             const IcpOptions& options) {
  const double moved_mm = ((pose * centre) - (start * centre)).norm();
  const double turned_deg = RadToDeg(Eigen::AngleAxisd(pose.R * start.R.transpose()).angle());
  return moved_mm > options.max_drift_mm || turned_deg > options.max_drift_deg;
}

// `update` (rotation about `pivot`, then translation) applied to `pose`.
Pose ApplyUpdate(const Pose& pose, const Eigen::Matrix<double, 6, 1>& update,
                 const Eigen::Vector3d& pivot) {
  const Eigen::Vector3d omega = update.head<3>();
  const double angle = omega.norm();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (angle > 1e-12) rotation = Eigen::AngleAxisd(angle, omega / angle).toRotationMatrix();
  return Pose{rotation, pivot - rotation * pivot + update.tail<3>()} * pose;
}

}  // namespace

void IcpOptions::Validate() const {
  if (max_iterations < 1 || renders < 1) throw Error("icp: iterations and renders must be >= 1");
  if (!(final_max_distance_mm > 0.0) || !(initial_max_distance_mm >= final_max_distance_mm)) {
    throw Error("icp: need 0 < final gate <= initial gate");
  }
  if (!(max_step_mm > 0.0) || !(max_step_deg > 0.0) || !(max_drift_mm > 0.0) ||
      !(max_drift_deg > 0.0)) {
    throw Error("icp: step and drift limits must be positive");
  }
  if (!(huber_mm > 0.0) || sample_step_px < 1 || !(convergence_mm >= 0.0)) {
    throw Error("icp: huber scale and sampling step must be positive");
  }
}

IcpResult RefinePoseIcp(const RenderMesh& mesh, const PinholeCamera& camera,
                        const cv::Mat& depth_mm, const Pose& initial, const IcpOptions& options) {
  options.Validate();
  if (depth_mm.type() != CV_32F || depth_mm.cols != camera.width ||
      depth_mm.rows != camera.height) {
    throw Error("icp: depth must be CV_32F mm of the camera's size");
  }
  IcpResult result;
  result.cam_from_model = initial;
  const int per_render = std::max(1, options.max_iterations / options.renders);
  std::vector<SurfaceSample> samples;
  Eigen::Matrix<double, 6, 1> velocity = Eigen::Matrix<double, 6, 1>::Zero();
  const Eigen::Vector3d centre = MeanPosition(mesh);
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    if (iteration % per_render == 0) {
      samples = SampleVisibleSurface(mesh, camera, result.cam_from_model, options.sample_step_px);
      if (samples.empty()) return result;
    }
    // The gate shrinks geometrically: wide while the pose is rough, tight once it is close.
    const double gate = std::max(options.final_max_distance_mm,
                                 options.initial_max_distance_mm * std::pow(0.7, iteration));
    const Eigen::Vector3d pivot = result.cam_from_model * centre;
    const StepResult step =
        SolveStep(samples, result.cam_from_model, camera, depth_mm, gate, options.huber_mm, pivot);
    result.iterations = iteration + 1;
    if (step.inliers < 6) break;
    Eigen::Matrix<double, 6, 1> move = step.update;
    if (KeepsDirection(step.update, velocity)) move += kMomentum * velocity;
    velocity = ClampStep(move, options);
    result.cam_from_model = ApplyUpdate(result.cam_from_model, velocity, pivot);
    const double motion_mm =
        step.update.tail<3>().norm() + step.update.head<3>().norm() * kRotationArmMm;
    if (motion_mm < options.convergence_mm && gate <= options.final_max_distance_mm) {
      result.converged = true;
      break;
    }
  }
  if (Drifted(initial, result.cam_from_model, centre, options)) {
    result.cam_from_model = initial;
    result.converged = false;
  }
  const StepResult final_step =
      SolveStep(samples, result.cam_from_model, camera, depth_mm, options.final_max_distance_mm,
                options.huber_mm, result.cam_from_model * centre);
  result.inlier_ratio =
      samples.empty() ? 0.0 : static_cast<double>(final_step.inliers) / samples.size();
  result.rmse_mm =
      final_step.inliers > 0 ? std::sqrt(final_step.squared_error / final_step.inliers) : 0.0;
  return result;
}

}  // namespace layermod
