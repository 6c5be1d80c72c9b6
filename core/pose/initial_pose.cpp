// SPDX-License-Identifier: MIT
#include "pose/initial_pose.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace layermod {

double EstimateCentreDepthMm(const TemplateRecord& tmpl, cv::Point box_tl_px,
                             const cv::Mat& depth_mm) {
  if (tmpl.levels.empty() || depth_mm.empty()) return 0.0;
  std::vector<float> depths;
  for (const Feature& feature : tmpl.levels[0].features) {
    if (feature.modality != Modality::kDepthNormal) continue;
    const cv::Point pixel = box_tl_px + cv::Point(feature.x, feature.y);
    if (pixel.x < 0 || pixel.y < 0 || pixel.x >= depth_mm.cols || pixel.y >= depth_mm.rows) {
      continue;
    }
    const float depth = depth_mm.at<float>(pixel);
    if (depth > 0.0f) depths.push_back(depth);
  }
  if (depths.size() < 3) return 0.0;
  auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  return *middle + tmpl.centre_minus_surface_mm;
}

Pose PoseFromMatch(const TemplateRecord& tmpl, cv::Point box_tl_px, double centre_depth_mm,
                   const Eigen::Vector3d& model_centre, const PinholeCamera& camera) {
  const Eigen::Vector2d centre_px(box_tl_px.x + tmpl.centre_offset_px.x,
                                  box_tl_px.y + tmpl.centre_offset_px.y);
  const Eigen::Vector3d ray = camera.Backproject(centre_px, 1.0).normalized();
  const Eigen::Matrix3d ray_from_axis =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), ray).toRotationMatrix();
  Pose pose;
  pose.R = ray_from_axis * tmpl.cam_from_model.R;
  // The centre lies on the ray; `centre_depth_mm` is its z (depth maps measure z, not range).
  const Eigen::Vector3d centre_in_cam = ray * (centre_depth_mm / ray.z());
  pose.t = centre_in_cam - pose.R * model_centre;
  return pose;
}

}  // namespace layermod
