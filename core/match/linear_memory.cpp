// SPDX-License-Identifier: MIT
#include "match/linear_memory.h"

#include <string>

#include "match/spread.h"
#include "util/error.h"

namespace layermod {
namespace {

int CeilDiv(int value, int divisor) { return (value + divisor - 1) / divisor; }

void CheckLinearizeInput(const cv::Mat& response_map, int spread_px) {
  if (spread_px < 1 || spread_px > kMaxSpreadPx) {
    throw Error("spread T = " + std::to_string(spread_px) + " is outside 1.." +
                std::to_string(kMaxSpreadPx));
  }
  if (!response_map.empty() && response_map.type() != CV_8UC1) {
    throw Error("response map must be CV_8UC1, got type " + std::to_string(response_map.type()));
  }
}

}  // namespace

LinearMemory Linearize(const cv::Mat& response_map, int spread_px) {
  CheckLinearizeInput(response_map, spread_px);
  LinearMemory linear;
  linear.spread_px = spread_px;
  if (response_map.empty()) return linear;
  const int t = spread_px;
  linear.grid_size = cv::Size(CeilDiv(response_map.cols, t), CeilDiv(response_map.rows, t));
  linear.memories = cv::Mat::zeros(t * t, linear.CellCount() + kSimdBlock, CV_8UC1);
  const int grid_width = linear.grid_size.width;
  // Read each image row once, sequentially; it feeds the T memories of its in-cell row.
  for (int y = 0; y < response_map.rows; ++y) {
    const std::uint8_t* src = response_map.ptr<std::uint8_t>(y);
    const int r = y % t;
    const int row_start = (y / t) * grid_width;
    for (int c = 0; c < t; ++c) {
      std::uint8_t* dst = linear.memories.ptr<std::uint8_t>(r * t + c) + row_start;
      int gx = 0;
      for (int x = c; x < response_map.cols; x += t) dst[gx++] = src[x];
    }
  }
  return linear;
}

LinearMemory ResponseAtLeast(const LinearMemory& memory, const LinearMemory& floors) {
  if (floors.spread_px != memory.spread_px || floors.grid_size != memory.grid_size) {
    throw Error("linear memories of different T or grids");
  }
  LinearMemory result;
  result.spread_px = memory.spread_px;
  result.grid_size = memory.grid_size;
  cv::max(memory.memories, floors.memories, result.memories);  // the slack stays 0
  return result;
}

LinearMemories Linearize(const std::array<cv::Mat, kOrientationCount>& response_maps,
                         int spread_px) {
  LinearMemories all;
  all.spread_px = spread_px;
  for (int label = 0; label < kOrientationCount; ++label) {
    if (response_maps[label].size() != response_maps[0].size()) {
      throw Error("response maps of one modality must all have the same size");
    }
    all.orientations[label] = Linearize(response_maps[label], spread_px);
  }
  all.grid_size = all.orientations[0].grid_size;
  return all;
}

}  // namespace layermod
