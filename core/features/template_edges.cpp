// SPDX-License-Identifier: MIT
#include "features/template_edges.h"

#include <cmath>
#include <string>

#include "features/depth_edges.h"
#include "util/error.h"

namespace layermod {
namespace {

void CheckArguments(const RenderedView& view, const cv::Point2d& centre_px, double diameter_mm,
                    double layer_depth_mm) {
  if (!(diameter_mm > 0.0) || !(layer_depth_mm > 0.0) || !std::isfinite(diameter_mm) ||
      !std::isfinite(layer_depth_mm) || !std::isfinite(centre_px.x) ||
      !std::isfinite(centre_px.y)) {
    throw Error("TemplateDepthEdgeCount: diameter, layer depth and centre must be finite, > 0");
  }
  if (view.roi.area() == 0) return;
  if (view.depth_mm.type() != CV_32F || view.depth_mm.size() != view.roi.size() ||
      view.mask.type() != CV_8U || view.mask.size() != view.roi.size()) {
    throw Error("TemplateDepthEdgeCount: view depth (CV_32F) and mask (CV_8U) must match its roi");
  }
}

cv::Rect EdgeWindow(const PinholeCamera& camera, const cv::Point2d& centre_px, double diameter_mm,
                    double layer_depth_mm) {
  const double side = std::round(camera.fx * diameter_mm / layer_depth_mm);
  if (!(side >= 1.0 && side <= 16384.0)) {
    throw Error("TemplateDepthEdgeCount: window side " + std::to_string(side) +
                " px is out of range 1..16384");
  }
  const int side_px = static_cast<int>(side);
  const cv::Point corner(static_cast<int>(std::lround(centre_px.x - (side_px - 1) / 2.0)),
                         static_cast<int>(std::lround(centre_px.y - (side_px - 1) / 2.0)));
  return {corner, cv::Size(side_px, side_px)};
}

}  // namespace

cv::Mat SupportPlaneDepth(const PinholeCamera& camera, const SupportPlane& plane,
                          const cv::Rect& window, float far_mm) {
  // Plane n . X = k in camera coordinates; the ray through a pixel is X = z * (x', y', 1).
  const Eigen::Vector3d normal = plane.cam_from_model.R.col(2);
  const double k = normal.dot(plane.cam_from_model * Eigen::Vector3d(0.0, 0.0, plane.z_mm));
  cv::Mat depth(window.size(), CV_32F);
  for (int row = 0; row < window.height; ++row) {
    auto* out = depth.ptr<float>(row);
    const double y = (window.y + row - camera.cy) / camera.fy;
    for (int col = 0; col < window.width; ++col) {
      const double x = (window.x + col - camera.cx) / camera.fx;
      const double denominator = normal.x() * x + normal.y() * y + normal.z();
      const double z = std::abs(denominator) > 1e-9 ? k / denominator : -1.0;
      out[col] = z > 0.0 && z < far_mm ? static_cast<float>(z) : far_mm;
    }
  }
  return depth;
}

int TemplateDepthEdgeCount(const RenderedView& view, const PinholeCamera& camera,
                           const cv::Point2d& centre_px, double diameter_mm, double layer_depth_mm,
                           float edge_threshold_mm, const SupportPlane* support) {
  CheckArguments(view, centre_px, diameter_mm, layer_depth_mm);
  const cv::Rect window = EdgeWindow(camera, centre_px, diameter_mm, layer_depth_mm);
  const auto far_mm = static_cast<float>(layer_depth_mm + 2.0 * diameter_mm);
  cv::Mat depth = support != nullptr ? SupportPlaneDepth(camera, *support, window, far_mm)
                                     : cv::Mat(window.size(), CV_32F, cv::Scalar(far_mm));
  const cv::Rect overlap = window & view.roi;
  if (overlap.area() > 0) {
    const cv::Mat source = view.depth_mm(overlap - view.roi.tl());
    const cv::Mat object = (view.mask(overlap - view.roi.tl()) > 0) & (source > 0.0f);
    source.copyTo(depth(overlap - window.tl()), object);
  }
  return CountDepthEdges(depth, edge_threshold_mm);
}

}  // namespace layermod
