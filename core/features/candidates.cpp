// SPDX-License-Identifier: MIT
#include "features/candidates.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "features/quantize.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr float kStableLabelPx = 2.0f;

// Neighbour step along a gradient label's orientation (label k is at 22.5 k deg), to 45 deg.
cv::Point AcrossEdgeStep(int label) {
  static const cv::Point kSteps[4] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}};
  return kSteps[((label + 1) / 2) % 4];
}

bool IsRidge(const cv::Mat& magnitude, int x, int y, int label) {
  const cv::Point step = AcrossEdgeStep(label);
  const float m = magnitude.at<float>(y, x);
  const cv::Point before(x - step.x, y - step.y), after(x + step.x, y + step.y);
  const cv::Rect image({}, magnitude.size());
  if (image.contains(before) && magnitude.at<float>(before) > m) return false;
  if (image.contains(after) && magnitude.at<float>(after) > m) return false;
  return true;
}

// One 3-4 chamfer sweep over an image with a 1 px border of zeros (a label border all round).
// The previous row's three neighbours are taken in a branch-free loop that vectorises; only the
// left (or right) neighbour needs the sequential pass.
void ChamferSweep(cv::Mat* distance, bool forward) {
  const int rows = distance->rows, cols = distance->cols;
  for (int i = 1; i < rows - 1; ++i) {
    const int y = forward ? i : rows - 1 - i;
    auto* __restrict row = distance->ptr<std::int32_t>(y);
    const auto* __restrict prev = distance->ptr<std::int32_t>(forward ? y - 1 : y + 1);
    for (int x = 1; x < cols - 1; ++x) {
      const std::int32_t diagonal = std::min(prev[x - 1], prev[x + 1]) + 4;
      row[x] = std::min(row[x], std::min(prev[x] + 3, diagonal));
    }
    if (forward) {
      for (int x = 1; x < cols - 1; ++x) row[x] = std::min(row[x], row[x - 1] + 3);
    } else {
      for (int x = cols - 2; x > 0; --x) row[x] = std::min(row[x], row[x + 1] + 3);
    }
  }
}

}  // namespace

std::vector<FeatureCandidate> ColorGradientCandidates(const cv::Mat& bgr, const cv::Mat& region,
                                                      cv::Point offset_px, float weak_magnitude,
                                                      float strong_magnitude) {
  if (region.type() != CV_8U || region.size() != bgr.size()) {
    throw Error("ColorGradientCandidates: region must be CV_8U of the image's size");
  }
  std::vector<FeatureCandidate> candidates;
  cv::Mat magnitude;
  const cv::Mat quantized = QuantizeColorGradients(bgr, weak_magnitude, &magnitude);
  for (int y = 0; y < quantized.rows; ++y) {
    const auto* q = quantized.ptr<std::uint8_t>(y);
    const auto* m = magnitude.ptr<float>(y);
    const auto* r = region.ptr<std::uint8_t>(y);
    for (int x = 0; x < quantized.cols; ++x) {
      if (r[x] == 0 || q[x] == 0 || !(m[x] > strong_magnitude)) continue;
      const int label = LabelOfBit(q[x]);
      if (!IsRidge(magnitude, x, y, label)) continue;
      candidates.push_back(
          {x + offset_px.x, y + offset_px.y, static_cast<std::uint8_t>(label), m[x]});
    }
  }
  return candidates;
}

cv::Mat LabelBorderDistance(const cv::Mat& quantized, const cv::Mat& interior) {
  constexpr std::int32_t kFar = 1 << 28;
  cv::Mat distance = cv::Mat::zeros(quantized.rows + 2, quantized.cols + 2, CV_32S);
  cv::Mat labels;  // replicated border: the image edge is no label border
  cv::copyMakeBorder(quantized, labels, 1, 1, 1, 1, cv::BORDER_REPLICATE);
  for (int y = 0; y < quantized.rows; ++y) {
    const std::uint8_t* __restrict q = labels.ptr<std::uint8_t>(y + 1) + 1;
    const std::uint8_t* __restrict up = labels.ptr<std::uint8_t>(y) + 1;
    const std::uint8_t* __restrict down = labels.ptr<std::uint8_t>(y + 2) + 1;
    const std::uint8_t* __restrict in = interior.ptr<std::uint8_t>(y);
    std::int32_t* __restrict out = distance.ptr<std::int32_t>(y + 1) + 1;
    for (int x = 0; x < quantized.cols; ++x) {
      const bool same =
          (q[x] == q[x - 1]) & (q[x] == q[x + 1]) & (q[x] == up[x]) & (q[x] == down[x]);
      out[x] = ((in[x] != 0) & (q[x] != 0) & same) ? kFar : 0;
    }
  }
  ChamferSweep(&distance, true);
  ChamferSweep(&distance, false);
  cv::Mat distance_px;
  distance(cv::Rect(1, 1, quantized.cols, quantized.rows))
      .convertTo(distance_px, CV_32F, 1.0 / 3.0);
  return distance_px;
}

std::vector<FeatureCandidate> DepthNormalCandidates(const cv::Mat& depth_mm,
                                                    const cv::Mat& interior,
                                                    const PinholeCamera& camera,
                                                    cv::Point offset_px, float max_depth_step_mm,
                                                    NormalFrame frame, int count) {
  if (interior.type() != CV_8U || interior.size() != depth_mm.size()) {
    throw Error("DepthNormalCandidates: interior must be CV_8U of the depth map's size");
  }
  std::vector<FeatureCandidate> candidates;
  const cv::Mat normals =
      ComputeDepthNormals(depth_mm, camera, offset_px, max_depth_step_mm, frame, interior);
  const cv::Mat quantized = QuantizeNormals(normals);
  const cv::Mat stability = LabelBorderDistance(quantized, interior);
  for (int y = (offset_px.y & 1); y < quantized.rows; y += 2) {
    const auto* q = quantized.ptr<std::uint8_t>(y);
    const auto* in = interior.ptr<std::uint8_t>(y);
    const auto* score = stability.ptr<float>(y);
    for (int x = (offset_px.x & 1); x < quantized.cols; x += 2) {
      if (in[x] == 0 || q[x] == 0) continue;
      candidates.push_back({x + offset_px.x, y + offset_px.y,
                            static_cast<std::uint8_t>(LabelOfBit(q[x])), score[x]});
    }
  }
  const auto near_border = [](const FeatureCandidate& c) { return c.score < kStableLabelPx; };
  const auto stable = std::count_if(candidates.begin(), candidates.end(),
                                    [&](const FeatureCandidate& c) { return !near_border(c); });
  if (stable >= count) std::erase_if(candidates, near_border);
  return candidates;
}

}  // namespace layermod
