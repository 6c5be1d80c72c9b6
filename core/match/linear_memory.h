// SPDX-License-Identifier: MIT
// Stage 3 of LineMOD matching (PAMI 2012, §2.5): linearized response maps. Regrouping a response
// map by pixel offset inside the T x T cells makes the responses that one feature contributes to
// consecutive grid positions contiguous, so a template is scored over the whole grid with long
// runs of SIMD additions.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>

#include "match/response_maps.h"

namespace layermod {

// The T*T linear memories of one response map. The map is cut into T x T cells; the grid has
// ceil(W / T) x ceil(H / T) cells (a partial last column/row of cells is padded with 0, so any
// image size works). Memory (r, c) holds, for every cell in row-major order, the response at
// offset (c, r) inside the cell:
//   Memory(r, c)[gy * grid_size.width + gx] == response(gy * T + r, gx * T + c)  (0 outside).
// Each memory is followed by kSimdBlock bytes of slack (0) for the block kernels.
struct LinearMemory {
  int spread_px = 0;   // T
  cv::Size grid_size;  // cells
  cv::Mat memories;    // CV_8UC1, T*T rows x (cells + kSimdBlock) columns; row r * T + c

  int CellCount() const { return grid_size.area(); }
  const std::uint8_t* Memory(int r, int c) const {
    return memories.ptr<std::uint8_t>(r * spread_px + c);
  }
};

// The linear memories of one response map (CV_8UC1, any size; empty -> empty grid).
// Throws Error for another type or T outside 1..kMaxSpreadPx.
LinearMemory Linearize(const cv::Mat& response_map, int spread_px);

// All 8 orientations of one modality at one pyramid level.
struct LinearMemories {
  int spread_px = 0;
  cv::Size grid_size;
  std::array<LinearMemory, kOrientationCount> orientations;
};

LinearMemories Linearize(const std::array<cv::Mat, kOrientationCount>& response_maps,
                         int spread_px);

// The larger of the two responses everywhere: `floors` is another map of the same size,
// linearized with the same T. Throws Error for another layout.
LinearMemory ResponseAtLeast(const LinearMemory& memory, const LinearMemory& floors);

}  // namespace layermod
