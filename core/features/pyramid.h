// SPDX-License-Identifier: MIT
// Image pyramid shared by template extraction and scene detection, so both see the same pixels.
// Convention: pixel u of level k + 1 is centred on pixel 2u of level k (cv::pyrDown's); sizes are
// (size + 1) / 2.
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"

namespace layermod {

// Colour (or any image cv::pyrDown accepts): Gaussian 5x5 then every second pixel.
cv::Mat DownsampleColor(const cv::Mat& image);

// Depth, mask or label images: every second pixel, no mixing of values, so depth stays a real
// surface depth (no blending of object and background at silhouettes) and invalid stays invalid.
cv::Mat DownsampleNearest(const cv::Mat& image);

// The camera seen at pyramid `level` with the convention above: f / 2^k and c / 2^k (not
// PinholeCamera::Scaled, whose pixel centres follow box averaging).
PinholeCamera PyramidLevelCamera(const PinholeCamera& camera, int level);

}  // namespace layermod
