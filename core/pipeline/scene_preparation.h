// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "features/feature_options.h"
#include "geometry/camera.h"
#include "match/matcher.h"

namespace layermod {

// Quantizes a capture at every pyramid level (colour gradients; depth normals when `depth_mm`
// is not empty) and prepares it for matching, with the same parameters the templates used.
PreparedScene PrepareScene(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, const FeatureOptions& features,
                           SimdPath simd = SimdPath::kAuto);

}  // namespace layermod
