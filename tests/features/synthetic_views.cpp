// SPDX-License-Identifier: MIT
#include "features/synthetic_views.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace layermod::test {
namespace {

RenderedView EmptyView(const cv::Rect& roi) {
  RenderedView view;
  view.roi = roi;
  view.depth_mm = cv::Mat::zeros(roi.size(), CV_32F);
  view.mask = cv::Mat::zeros(roi.size(), CV_8U);
  view.normals = cv::Mat::zeros(roi.size(), CV_32FC3);
  view.color = cv::Mat::zeros(roi.size(), CV_8UC3);
  return view;
}

}  // namespace

cv::Mat PlaneDepth(const PinholeCamera& camera, const cv::Rect& roi,
                   const Eigen::Vector3d& point_mm, const Eigen::Vector3d& normal) {
  cv::Mat depth(roi.size(), CV_32F);
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const Eigen::Vector3d ray =
          camera.Backproject(Eigen::Vector2d(u + roi.x, v + roi.y), 1.0);  // z = 1
      depth.at<float>(v, u) = static_cast<float>(normal.dot(point_mm) / normal.dot(ray));
    }
  }
  return depth;
}

RenderedView PyramidView(const cv::Rect& roi, cv::Point centre_px, int half_px, float base_mm,
                         float height_mm) {
  RenderedView view = EmptyView(roi);
  const double base_inverse = 1.0 / base_mm;
  const double slope = (1.0 / (base_mm - height_mm) - base_inverse) / half_px;
  const cv::Vec3b face_colors[4] = {{40, 60, 200}, {200, 80, 40}, {60, 190, 60}, {190, 190, 50}};
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const int du = u + roi.x - centre_px.x;
      const int dv = v + roi.y - centre_px.y;
      const int ring = std::max(std::abs(du), std::abs(dv));
      if (ring > half_px) continue;
      view.depth_mm.at<float>(v, u) =
          static_cast<float>(1.0 / (base_inverse + slope * (half_px - ring)));
      view.mask.at<std::uint8_t>(v, u) = 255;
      const int face = std::abs(du) >= std::abs(dv) ? (du >= 0 ? 0 : 1) : (dv >= 0 ? 2 : 3);
      view.color.at<cv::Vec3b>(v, u) = face_colors[face];
    }
  }
  return view;
}

RenderedView DiscView(const cv::Rect& roi, cv::Point2d centre_px, double radius_px,
                      float depth_mm) {
  RenderedView view = EmptyView(roi);
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const double dx = u + roi.x - centre_px.x;
      const double dy = v + roi.y - centre_px.y;
      if (dx * dx + dy * dy > radius_px * radius_px) continue;
      view.depth_mm.at<float>(v, u) = depth_mm;
      view.mask.at<std::uint8_t>(v, u) = 255;
      view.color.at<cv::Vec3b>(v, u) = {150, 150, 150};
      view.normals.at<cv::Vec3f>(v, u) = {0.0f, 0.0f, -1.0f};
    }
  }
  return view;
}

}  // namespace layermod::test
