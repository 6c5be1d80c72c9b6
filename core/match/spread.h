// SPDX-License-Identifier: MIT
// Stage 1 of LineMOD matching (Hinterstoisser et al., PAMI 2012, §2.3): spreading the quantized
// orientations so that a feature tolerates small shifts and deformations.
#pragma once

#include <opencv2/core.hpp>

namespace layermod {

// Largest spread T the matcher accepts (LineMOD uses 4..8; T*T linear memories are kept).
inline constexpr int kMaxSpreadPx = 16;

// Each pixel receives the OR of the quantized bitmasks in the T x T block whose TOP-LEFT corner it
// is: pixels (x + dx, y + dy) with 0 <= dx, dy < T; pixels outside the image count as 0 (OpenCV's
// convention). Consequence used by the matcher: a template evaluated at top-left p scores each
// feature f fully when the scene carries its orientation anywhere in [p + f, p + f + T), so a true
// placement p0 gives its full score at every p in (p0 - T, p0] -- a grid position g * T stands for
// the true positions g * T .. g * T + T - 1.
// `quantized`: CV_8UC1 bitmasks (features stage encoding); empty in -> empty out. Same size out.
// Throws Error for another type or T outside 1..kMaxSpreadPx.
cv::Mat SpreadOrientations(const cv::Mat& quantized, int spread_px);

}  // namespace layermod
