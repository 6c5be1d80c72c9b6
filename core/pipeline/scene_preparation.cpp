// SPDX-License-Identifier: MIT
#include "pipeline/scene_preparation.h"

#include <array>
#include <vector>

#include "features/pyramid.h"
#include "features/quantize.h"

namespace layermod {

PreparedScene PrepareScene(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, const FeatureOptions& features,
                           SimdPath simd) {
  std::vector<std::array<cv::Mat, kModalityCount>> quantized(
      static_cast<std::size_t>(features.pyramid_levels));
  cv::Mat color = color_bgr;
  cv::Mat depth = depth_mm;
  for (int level = 0; level < features.pyramid_levels; ++level) {
    if (level > 0) {
      color = DownsampleColor(color);
      if (!depth.empty()) depth = DownsampleNearest(depth);
    }
    auto& modalities = quantized[static_cast<std::size_t>(level)];
    modalities[ModalityIndex(Modality::kColorGradient)] =
        QuantizeColorGradients(color, features.weak_gradient);
    if (!depth.empty()) {
      const cv::Mat normals = ComputeDepthNormals(depth, PyramidLevelCamera(camera, level),
                                                  cv::Point(0, 0),
                                                  features.max_normal_depth_step_mm);
      modalities[ModalityIndex(Modality::kDepthNormal)] = QuantizeNormals(normals);
    }
  }
  return PreparedScene(quantized, features.spread_px, simd);
}

}  // namespace layermod
