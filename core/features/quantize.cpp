// SPDX-License-Identifier: MIT
#include "features/quantize.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "util/error.h"

namespace layermod {
namespace {

// floor(atan2(y, x) / 45 deg) in 0..7 from comparisons only (on scene-sized images atan2 would
// dominate the stage). (0, 0) gives 7; callers exclude it.
inline int Octant(float x, float y) {
  const bool upper = (y > 0.0f) | ((y == 0.0f) & (x > 0.0f));
  const float ux = upper ? x : -x, uy = upper ? y : -y;  // rotated into [0, 180) deg
  const int right = uy < ux ? 0 : 1;
  const int left = uy > -ux ? 2 : 3;
  return (ux > 0.0f ? right : left) + (upper ? 0 : 4);
}

// Rotates (x, y) by +22.5 deg, so that octants become bins centred on multiples of 45 deg.
inline int CentredOctant(float x, float y) {
  constexpr float kCos = 0.92387953f;  // cos 22.5 deg
  constexpr float kSin = 0.38268343f;  // sin 22.5 deg
  return Octant(kCos * x - kSin * y, kSin * x + kCos * y);
}

// Row scratch of the gradient stage, reused for every row: no image-sized temporaries besides the
// blurred image (their page faults used to cost as much as the arithmetic).
struct GradientRowScratch {
  std::vector<std::int16_t> padded[3];  // rows y-1, y, y+1 of the blurred image, 1 px replicated
  std::vector<std::int16_t> gx, gy;     // Sobel per channel, interleaved like the image
  std::vector<std::int32_t> sq;         // gx^2 + gy^2 per channel

  explicit GradientRowScratch(int width)
      : gx(3 * static_cast<size_t>(width)), gy(gx.size()), sq(gx.size()) {
    for (auto& row : padded) row.resize(3 * (static_cast<size_t>(width) + 2));
  }
};

// Copies a BGR row into `out` with its end pixels replicated one pixel further on each side.
void PadRow(const std::uint8_t* bgr, int width, std::vector<std::int16_t>* out) {
  std::int16_t* o = out->data();
  for (int i = 0; i < 3 * width; ++i) o[3 + i] = bgr[i];
  for (int c = 0; c < 3; ++c) {
    o[c] = bgr[c];
    o[3 * (width + 1) + c] = bgr[3 * (width - 1) + c];
  }
}

// 3x3 Sobel of one row of the blurred image (rows replicated at the image border), all channels
// at once: in the interleaved layout the horizontal neighbours are 3 elements away, so the loops
// are contiguous and vectorise.
void SobelRow(const cv::Mat& blurred, int y, GradientRowScratch* scratch) {
  const int width = blurred.cols;
  const int rows[3] = {std::max(y - 1, 0), y, std::min(y + 1, blurred.rows - 1)};
  for (int r = 0; r < 3; ++r) {
    PadRow(blurred.ptr<std::uint8_t>(rows[r]), width, &scratch->padded[r]);
  }
  const std::int16_t* __restrict up = scratch->padded[0].data() + 3;
  const std::int16_t* __restrict mid = scratch->padded[1].data() + 3;
  const std::int16_t* __restrict down = scratch->padded[2].data() + 3;
  std::int16_t* __restrict gx = scratch->gx.data();
  std::int16_t* __restrict gy = scratch->gy.data();
  std::int32_t* __restrict sq = scratch->sq.data();
  for (int i = 0; i < 3 * width; ++i) {
    gx[i] = static_cast<std::int16_t>((up[i + 3] - up[i - 3]) + 2 * (mid[i + 3] - mid[i - 3]) +
                                      (down[i + 3] - down[i - 3]));
    gy[i] = static_cast<std::int16_t>((down[i - 3] - up[i - 3]) + 2 * (down[i] - up[i]) +
                                      (down[i + 3] - up[i + 3]));
    sq[i] = gx[i] * gx[i] + gy[i] * gy[i];
  }
}

// Per pixel of one row: the strongest channel's magnitude, and its packed vote (4 bits per label
// in a uint32, so a 3x3 sum of at most 9 never carries over; 0 when weak).
void StrongestChannelRow(const GradientRowScratch& scratch, int width, float weak_sq,
                         float* __restrict magnitude, std::uint32_t* __restrict vote) {
  const std::int32_t* sq = scratch.sq.data();
  for (int x = 0; x < width; ++x) {
    const std::int32_t* s = sq + 3 * static_cast<ptrdiff_t>(x);
    const int best = s[1] > s[0] ? (s[2] > s[1] ? 2 : 1) : (s[2] > s[0] ? 2 : 0);
    const auto best_sq = static_cast<float>(s[best]);
    magnitude[x] = best_sq;  // squared for now: one vectorised sqrt pass below
    // Most pixels are weak: a branch skips their label.
    const int i = 3 * x + best;
    vote[x] =
        best_sq > weak_sq ? 1u << (4 * GradientOrientationLabel(scratch.gx[i], scratch.gy[i])) : 0u;
  }
  for (int x = 0; x < width; ++x) magnitude[x] = std::sqrt(magnitude[x]);
}

// The label with at least kGradientMinVotes votes as `1 << label`, or 0. Adding (8 - min) to
// every nibble sets its bit 3 exactly when the count reaches the minimum; with 9 voters at most one
// label can reach 5.
inline std::uint8_t MajorityBit(std::uint32_t packed_counts) {
  static_assert(kGradientMinVotes >= 5 && kGradientMinVotes <= 8, "one winner, no nibble carry");
  constexpr std::uint32_t kBias = (8u - kGradientMinVotes) * 0x11111111u;
  const std::uint32_t winners = (packed_counts + kBias) & 0x88888888u;
  if (winners == 0) return 0;
  const int label = (__builtin_ctz(winners) - 3) / 4;
  return static_cast<std::uint8_t>(1u << label);
}

}  // namespace

// Doubling the angle maps g and -g to the same direction; bins of 45 deg on the doubled angle are
// bins of 22.5 deg on the orientation.
int GradientOrientationLabel(float dx, float dy) {
  return CentredOctant(dx * dx - dy * dy, 2.0f * dx * dy);
}

cv::Mat QuantizeColorGradients(const cv::Mat& bgr, float weak_magnitude, cv::Mat* magnitude_out) {
  if (bgr.type() != CV_8UC3) throw Error("QuantizeColorGradients: expected a CV_8UC3 BGR image");
  if (!(weak_magnitude >= 0.0f)) throw Error("QuantizeColorGradients: weak_magnitude must be >= 0");
  cv::Mat quantized(bgr.size(), CV_8U);
  cv::Mat magnitude(bgr.size(), CV_32F);
  if (!bgr.empty()) {
    cv::Mat blurred;  // LineMOD's light blur
    cv::GaussianBlur(bgr, blurred, cv::Size(7, 7), 0.0, 0.0, cv::BORDER_REPLICATE);
    const float weak_sq = weak_magnitude * weak_magnitude;
    const int width = bgr.cols;
    GradientRowScratch scratch(width);
    // Votes of rows y-1, y, y+1, each with a zero pixel at both ends (outside votes nothing).
    std::vector<std::uint32_t> votes[3];
    for (auto& row : votes) row.assign(static_cast<size_t>(width) + 2, 0u);
    std::vector<std::uint32_t> column_sum(static_cast<size_t>(width) + 2);
    auto compute_votes = [&](int y, std::vector<std::uint32_t>* out) {
      SobelRow(blurred, y, &scratch);
      StrongestChannelRow(scratch, width, weak_sq, magnitude.ptr<float>(y), out->data() + 1);
    };
    compute_votes(0, &votes[1]);
    for (int y = 0; y < bgr.rows; ++y) {
      if (y + 1 < bgr.rows) {
        compute_votes(y + 1, &votes[2]);
      } else {
        std::fill(votes[2].begin(), votes[2].end(), 0u);
      }
      for (size_t x = 0; x < column_sum.size(); ++x) {
        column_sum[x] = votes[0][x] + votes[1][x] + votes[2][x];
      }
      const std::uint32_t* own = votes[1].data() + 1;
      auto* out = quantized.ptr<std::uint8_t>(y);
      for (int x = 0; x < width; ++x) {
        const std::uint32_t count = column_sum[x] + column_sum[x + 1] + column_sum[x + 2];
        out[x] = own[x] != 0 ? MajorityBit(count) : 0;
      }
      std::swap(votes[0], votes[1]);  // row y becomes y - 1, y + 1 becomes y
      std::swap(votes[1], votes[2]);
    }
  }
  if (magnitude_out != nullptr) *magnitude_out = magnitude;
  return quantized;
}

cv::Mat QuantizeNormals(const cv::Mat& normals, float frontal_tilt_deg) {
  if (normals.type() != CV_32FC3) throw Error("QuantizeNormals: expected CV_32FC3 normals");
  if (!(frontal_tilt_deg >= 0.0f && frontal_tilt_deg < 90.0f)) {
    throw Error("QuantizeNormals: frontal_tilt_deg must be in [0, 90)");
  }
  const float sin_frontal = std::sin(frontal_tilt_deg * static_cast<float>(CV_PI) / 180.0f);
  const float sin_frontal_sq = sin_frontal * sin_frontal;
  cv::Mat quantized(normals.size(), CV_8U);
  for (int y = 0; y < normals.rows; ++y) {
    const auto* n = normals.ptr<cv::Vec3f>(y);
    auto* out = quantized.ptr<std::uint8_t>(y);
    for (int x = 0; x < normals.cols; ++x) {
      const float xy_sq = n[x][0] * n[x][0] + n[x][1] * n[x][1];
      const float length_sq = xy_sq + n[x][2] * n[x][2];
      if (!(length_sq > 0.25f && length_sq < 4.0f)) {  // zero, NaN or inf
        out[x] = 0;
        continue;
      }
      const bool tilted = xy_sq > sin_frontal_sq * length_sq;
      const int label = tilted ? CentredOctant(n[x][0], n[x][1]) : kFrontalNormalLabel;
      out[x] = static_cast<std::uint8_t>(1u << label);
    }
  }
  return quantized;
}

}  // namespace layermod
