// SPDX-License-Identifier: MIT
#include "pipeline/layer_occluders.h"

#include <opencv2/core.hpp>

#include <cmath>

namespace layermod {

constexpr double kDepthNoiseShare = 0.02;

double NearestSurfaceMm(double layer_depth_mm, double sphere_radius_mm) {
  return layer_depth_mm * (1.0 - kDepthNoiseShare) - 1.5 * sphere_radius_mm;
}

std::vector<cv::Mat> WholeMillimetreDepths(const std::vector<cv::Mat>& depth_levels_mm) {
  std::vector<cv::Mat> whole_mm(depth_levels_mm.size());
  for (std::size_t level = 0; level < depth_levels_mm.size(); ++level) {
    depth_levels_mm[level].convertTo(whole_mm[level], CV_16U);
  }
  return whole_mm;
}

std::vector<cv::Mat> OccludersNearerThan(const std::vector<cv::Mat>& depth_levels_mm,
                                         double nearest_surface_mm, const cv::Rect& reach_px) {
  if (depth_levels_mm.empty() || nearest_surface_mm <= 0.0) return {};
  std::vector<cv::Mat> masks;
  masks.reserve(depth_levels_mm.size());
  for (std::size_t level = 0; level < depth_levels_mm.size(); ++level) {
    const cv::Mat& depth = depth_levels_mm[level];
    const int scale = 1 << level;
    const cv::Rect reach = cv::Rect(cv::Point(reach_px.x / scale, reach_px.y / scale),
                                    cv::Point((reach_px.br().x + scale - 1) / scale,
                                              (reach_px.br().y + scale - 1) / scale)) &
                           cv::Rect(cv::Point(0, 0), depth.size());
    cv::Mat mask = cv::Mat::zeros(depth.size(), CV_8UC1);
    if (!reach.empty()) {
      // Whole millimetres from 1 (0 is no depth) to the last one nearer than the bound.
      const double last_mm = std::ceil(nearest_surface_mm) - 1.0;
      cv::Mat reached = mask(reach);
      cv::inRange(depth(reach), 1.0, last_mm, reached);
    }
    masks.push_back(mask);
  }
  if (cv::countNonZero(masks.front()) == 0) return {};
  return masks;
}

}  // namespace layermod
