// SPDX-License-Identifier: MIT
#include "features/depth_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "util/error.h"

namespace layermod {

cv::Mat DepthEdgeStrength(const cv::Mat& depth_mm) {
  if (depth_mm.type() != CV_32F) throw Error("DepthEdgeMask: expected a CV_32F depth map");
  if (depth_mm.empty()) return cv::Mat(depth_mm.size(), CV_32F);
  // Whole-image operations (vectorized by OpenCV) rather than a 3x3 loop per pixel: the same
  // kernel, the same replicated border.
  const cv::Mat valid = (depth_mm > 0.0f) & (depth_mm < std::numeric_limits<float>::infinity());
  cv::Mat window_valid;
  cv::erode(valid, window_valid, cv::Mat(), cv::Point(-1, -1), 1, cv::BORDER_REPLICATE);
  cv::Mat gx, gy, strength;
  cv::Sobel(depth_mm, gx, CV_32F, 1, 0, 3, 1.0, 0.0, cv::BORDER_REPLICATE);
  cv::Sobel(depth_mm, gy, CV_32F, 0, 1, 3, 1.0, 0.0, cv::BORDER_REPLICATE);
  cv::magnitude(gx, gy, strength);
  strength *= 0.25f;
  strength.setTo(-1.0f, window_valid == 0);
  return strength;
}

cv::Mat DepthEdgeMaskFromStrength(const cv::Mat& strength, float threshold_mm) {
  if (strength.type() != CV_32F) throw Error("DepthEdgeMask: expected a CV_32F edge strength");
  if (!(threshold_mm > 0.0f) || !std::isfinite(threshold_mm)) {
    throw Error("DepthEdgeMask: threshold_mm must be positive and finite");
  }
  if (strength.empty()) return cv::Mat(strength.size(), CV_8U);
  return strength > threshold_mm;
}

cv::Mat DepthEdgeMask(const cv::Mat& depth_mm, float threshold_mm) {
  if (depth_mm.type() != CV_32F) throw Error("DepthEdgeMask: expected a CV_32F depth map");
  if (!(threshold_mm > 0.0f) || !std::isfinite(threshold_mm)) {
    throw Error("DepthEdgeMask: threshold_mm must be positive and finite");
  }
  return DepthEdgeMaskFromStrength(DepthEdgeStrength(depth_mm), threshold_mm);
}

cv::Mat FillDepthHolesFromFar(const cv::Mat& depth_mm, int max_gap_px) {
  if (depth_mm.type() != CV_32F) throw Error("FillDepthHolesFromFar: expected a CV_32F depth map");
  if (max_gap_px < 0) throw Error("FillDepthHolesFromFar: max_gap_px must be >= 0");
  // Invalid (NaN, inf, <= 0) as 0, so a max filter picks the farthest valid neighbour.
  cv::Mat filled = depth_mm.clone();
  filled.setTo(0.0f, ~((filled > 0.0f) & (filled < std::numeric_limits<float>::infinity())));
  if (max_gap_px == 0) return filled;
  // One max filter as wide as the largest gap: every pixel of such a hole sees its far side.
  const cv::Mat holes = filled <= 0.0f;
  cv::Mat farthest;
  cv::dilate(
      filled, farthest,
      cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * max_gap_px + 1, 2 * max_gap_px + 1)));
  farthest.copyTo(filled, holes);
  return filled;
}

int CountDepthEdges(const cv::Mat& depth_mm, float threshold_mm) {
  return cv::countNonZero(DepthEdgeMask(depth_mm, threshold_mm));
}

}  // namespace layermod
