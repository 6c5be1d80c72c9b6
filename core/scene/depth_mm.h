// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

namespace layermod {

// How raw depth values map to millimetres: a 16-bit value times `per_16u_unit_mm` (BOP's
// depth_scale), a float value times `per_float_unit_mm` (1 for millimetres, 1000 for metres).
struct DepthScale {
  double per_16u_unit_mm = 1.0;
  double per_float_unit_mm = 1.0;
};

// Depth as the detector takes it: CV_32F millimetres, 0 where nothing was measured. Accepts a
// single-channel CV_16U or CV_32F image; NaN, infinite and negative values become 0. A float
// image in millimetres that is already clean is returned as is (no copy). Throws Error saying
// what is wrong otherwise (empty, channels, 8-bit or another pixel type, a scale that is not a
// positive number).
cv::Mat DepthToMillimetres(const cv::Mat& depth, const DepthScale& scale = {});

}  // namespace layermod
