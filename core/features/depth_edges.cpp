// SPDX-License-Identifier: MIT
#include "features/depth_edges.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "util/error.h"

namespace layermod {

namespace {

inline bool ValidDepth(float z) { return z > 0.0f && z < std::numeric_limits<float>::infinity(); }
// The same as 0 / 1, for combining without branches.
inline int ValidBit(float z) { return static_cast<int>(ValidDepth(z)); }

// Sobel magnitude / 4 of the 3x3 window with columns left, centre, right of the rows above, at
// and below; -1 when the window holds an invalid depth. Written without branches so that the
// compiler vectorises the loop over a row's interior.
inline float WindowStrength(const float* up, const float* mid, const float* down, int left,
                            int centre, int right) {
  const int valid = ValidBit(up[left]) & ValidBit(up[centre]) & ValidBit(up[right]) &
                    ValidBit(mid[left]) & ValidBit(mid[centre]) & ValidBit(mid[right]) &
                    ValidBit(down[left]) & ValidBit(down[centre]) & ValidBit(down[right]);
  const float gx =
      (up[right] - up[left]) + 2.0f * (mid[right] - mid[left]) + (down[right] - down[left]);
  const float gy =
      (down[left] - up[left]) + 2.0f * (down[centre] - up[centre]) + (down[right] - up[right]);
  const float strength = 0.25f * std::sqrt(gx * gx + gy * gy);
  return valid != 0 ? strength : -1.0f;
}

// out[x] = max of in[x - half .. x + half] (clipped to the row) for non-negative values. Windows
// of 2^k values by doubling, then two overlapping ones: a handful of vectorised passes instead
// of one per window position.
void RowWindowMax(const float* in, int n, int half, float* out) {
  std::vector<float> span(static_cast<std::size_t>(n + 2 * half), 0.0f);  // zeros: neutral
  std::copy(in, in + n, span.begin() + half);
  const int window = 2 * half + 1;
  int width = 1;
  while (width * 2 <= window) {
    // span[i] becomes the max of [i, i + 2 * width): reads ahead only, so in place.
    const int limit = static_cast<int>(span.size()) - width;
    for (int i = 0; i < limit; ++i) span[i] = std::max(span[i], span[i + width]);
    width *= 2;
  }
  // [x - half, x + half] = [x - half, x - half + width) u (x + half - width, x + half].
  for (int x = 0; x < n; ++x) out[x] = std::max(span[x], span[x + window - width]);
}

}  // namespace

cv::Mat DepthEdgeStrength(const cv::Mat& depth_mm) {
  if (depth_mm.type() != CV_32F) throw Error("DepthEdgeMask: expected a CV_32F depth map");
  cv::Mat strength(depth_mm.size(), CV_32F);
  const int cols = depth_mm.cols;
  for (int y = 0; y < depth_mm.rows; ++y) {
    // Rows and columns outside the image replicate the border.
    const float* up = depth_mm.ptr<float>(std::max(y - 1, 0));
    const float* mid = depth_mm.ptr<float>(y);
    const float* down = depth_mm.ptr<float>(std::min(y + 1, depth_mm.rows - 1));
    float* out = strength.ptr<float>(y);
    for (int x = 1; x + 1 < cols; ++x) out[x] = WindowStrength(up, mid, down, x - 1, x, x + 1);
    if (cols > 0) out[0] = WindowStrength(up, mid, down, 0, 0, std::min(1, cols - 1));
    if (cols > 1) out[cols - 1] = WindowStrength(up, mid, down, cols - 2, cols - 1, cols - 1);
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
  return DepthEdgeMaskFromStrength(DepthEdgeStrength(depth_mm), threshold_mm);
}

cv::Mat FillDepthHolesFromFar(const cv::Mat& depth_mm, int max_gap_px) {
  if (depth_mm.type() != CV_32F) throw Error("FillDepthHolesFromFar: expected a CV_32F depth map");
  if (max_gap_px < 0) throw Error("FillDepthHolesFromFar: max_gap_px must be >= 0");
  // Invalid (NaN, inf, <= 0) as 0, so a max filter picks the farthest valid neighbour.
  cv::Mat filled(depth_mm.size(), CV_32F);
  for (int y = 0; y < depth_mm.rows; ++y) {
    const float* in = depth_mm.ptr<float>(y);
    float* out = filled.ptr<float>(y);
    for (int x = 0; x < depth_mm.cols; ++x) out[x] = ValidDepth(in[x]) ? in[x] : 0.0f;
  }
  if (max_gap_px == 0 || filled.empty()) return filled;
  // One max filter as wide as the largest gap (separable: rows, then columns; the window is
  // clipped at the image border): every pixel of such a hole sees its far side.
  cv::Mat row_max(filled.size(), CV_32F);
  for (int y = 0; y < filled.rows; ++y) {
    RowWindowMax(filled.ptr<float>(y), filled.cols, max_gap_px, row_max.ptr<float>(y));
  }
  for (int y = 0; y < filled.rows; ++y) {
    float* out = filled.ptr<float>(y);
    const int first = std::max(y - max_gap_px, 0);
    const int last = std::min(y + max_gap_px, filled.rows - 1);
    for (int x = 0; x < filled.cols; ++x) {
      if (out[x] > 0.0f) continue;  // valid: kept
      float farthest = 0.0f;
      for (int r = first; r <= last; ++r) farthest = std::max(farthest, row_max.at<float>(r, x));
      out[x] = farthest;
    }
  }
  return filled;
}

int CountDepthEdges(const cv::Mat& depth_mm, float threshold_mm) {
  return cv::countNonZero(DepthEdgeMask(depth_mm, threshold_mm));
}

}  // namespace layermod
