// SPDX-License-Identifier: MIT
#include "features/depth_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "util/error.h"

namespace layermod {
namespace {

inline bool ValidDepth(float z) { return z > 0.0f && std::isfinite(z); }

// Rows above, at and below `y` (replicated at the border), so a window never leaves the image.
struct RowTriple {
  const float* up;
  const float* mid;
  const float* down;
};

RowTriple RowsAround(const cv::Mat& depth_mm, int y) {
  return {depth_mm.ptr<float>(std::max(y - 1, 0)), depth_mm.ptr<float>(y),
          depth_mm.ptr<float>(std::min(y + 1, depth_mm.rows - 1))};
}

// Sobel magnitude / 4 at column x when the whole 3x3 window is valid, else -1.
float NormalisedSobel(const RowTriple& rows, int x, int cols) {
  const int left = std::max(x - 1, 0);
  const int right = std::min(x + 1, cols - 1);
  const float w[3][3] = {{rows.up[left], rows.up[x], rows.up[right]},
                         {rows.mid[left], rows.mid[x], rows.mid[right]},
                         {rows.down[left], rows.down[x], rows.down[right]}};
  for (const auto& row : w) {
    for (float z : row) {
      if (!ValidDepth(z)) return -1.0f;
    }
  }
  const float gx = (w[0][2] - w[0][0]) + 2.0f * (w[1][2] - w[1][0]) + (w[2][2] - w[2][0]);
  const float gy = (w[2][0] - w[0][0]) + 2.0f * (w[2][1] - w[0][1]) + (w[2][2] - w[0][2]);
  return 0.25f * std::sqrt(gx * gx + gy * gy);
}

}  // namespace

cv::Mat DepthEdgeStrength(const cv::Mat& depth_mm) {
  if (depth_mm.type() != CV_32F) throw Error("DepthEdgeMask: expected a CV_32F depth map");
  cv::Mat strength(depth_mm.size(), CV_32F);
  for (int y = 0; y < depth_mm.rows; ++y) {
    const RowTriple rows = RowsAround(depth_mm, y);
    auto* out = strength.ptr<float>(y);
    for (int x = 0; x < depth_mm.cols; ++x) out[x] = NormalisedSobel(rows, x, depth_mm.cols);
  }
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
