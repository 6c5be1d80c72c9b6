// SPDX-License-Identifier: MIT
#include "match/spread.h"

#include <string>

#include "util/error.h"

namespace layermod {
namespace {

void CheckSpreadInput(const cv::Mat& quantized, int spread_px) {
  if (spread_px < 1 || spread_px > kMaxSpreadPx) {
    throw Error("spread T = " + std::to_string(spread_px) + " is outside 1.." +
                std::to_string(kMaxSpreadPx));
  }
  if (!quantized.empty() && quantized.type() != CV_8UC1) {
    throw Error("quantized orientations must be CV_8UC1 bitmasks, got type " +
                std::to_string(quantized.type()));
  }
}

// dst(0..n) |= src(shift..shift + n) along columns (horizontal) or rows (vertical), where the
// source stays inside the image; the rest of the image has nothing to OR in.
void OrShiftedColumns(const cv::Mat& src, cv::Mat& dst, int shift) {
  if (shift >= src.cols) return;
  cv::Mat target = dst.colRange(0, src.cols - shift);
  cv::bitwise_or(target, src.colRange(shift, src.cols), target);
}

void OrShiftedRows(const cv::Mat& src, cv::Mat& dst, int shift) {
  if (shift >= src.rows) return;
  cv::Mat target = dst.rowRange(0, src.rows - shift);
  cv::bitwise_or(target, src.rowRange(shift, src.rows), target);
}

}  // namespace

cv::Mat SpreadOrientations(const cv::Mat& quantized, int spread_px) {
  CheckSpreadInput(quantized, spread_px);
  if (quantized.empty()) return {};
  // OR is associative, so the T x T block is T rows of T-wide row blocks: 2T passes, not T*T.
  cv::Mat rows_spread = quantized.clone();
  for (int dx = 1; dx < spread_px; ++dx) OrShiftedColumns(quantized, rows_spread, dx);
  cv::Mat spread = rows_spread.clone();
  for (int dy = 1; dy < spread_px; ++dy) OrShiftedRows(rows_spread, spread, dy);
  return spread;
}

}  // namespace layermod
