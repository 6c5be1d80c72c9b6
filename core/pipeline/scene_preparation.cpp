// SPDX-License-Identifier: MIT
#include "pipeline/scene_preparation.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

#include "features/pyramid.h"
#include "features/quantize.h"

namespace layermod {

namespace {

// The scene's pyramid, prepared; its depth levels into `depths` (empty Mats without depth).
PreparedScene PrepareAt(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                        const PinholeCamera& camera, cv::Point offset_px,
                        const FeatureOptions& features, SimdPath simd,
                        std::vector<cv::Mat>& depths, cv::Mat& gradient_labels) {
  const auto levels = static_cast<std::size_t>(features.pyramid_levels);
  std::vector<cv::Mat> colors(levels);
  depths.assign(levels, cv::Mat());
  for (std::size_t level = 0; level < levels; ++level) {
    colors[level] = level == 0 ? color_bgr : DownsampleColor(colors[level - 1]);
    if (!depth_mm.empty()) {
      depths[level] = level == 0 ? depth_mm : DownsampleNearest(depths[level - 1]);
    }
  }
  // Each (level, modality) pair is quantized independently: level 0's two are the big ones, so
  // two cores share the work evenly.
  const auto modalities = static_cast<std::size_t>(kModalityCount);
  std::vector<std::array<cv::Mat, kModalityCount>> quantized(levels);
  tbb::parallel_for(std::size_t{0}, levels * modalities, [&](std::size_t task) {
    const std::size_t level = task / modalities;
    const int scale = 1 << level;
    auto& maps = quantized[level];
    if (static_cast<int>(task % modalities) == ModalityIndex(Modality::kColorGradient)) {
      maps[ModalityIndex(Modality::kColorGradient)] =
          QuantizeColorGradients(colors[level], features.weak_gradient);
    } else if (!depths[level].empty()) {
      const cv::Mat normals = ComputeDepthNormals(
          depths[level], PyramidLevelCamera(camera, static_cast<int>(level)),
          cv::Point(offset_px.x / scale, offset_px.y / scale), features.max_normal_depth_step_mm);
      maps[ModalityIndex(Modality::kDepthNormal)] = QuantizeNormals(normals);
    }
  });
  gradient_labels = quantized[0][ModalityIndex(Modality::kColorGradient)];
  return PreparedScene(quantized, features.spread_px, simd);
}

}  // namespace

PreparedScene PrepareScene(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, const FeatureOptions& features,
                           SimdPath simd) {
  std::vector<cv::Mat> depths;
  cv::Mat gradient_labels;
  return PrepareAt(color_bgr, depth_mm, camera, cv::Point(0, 0), features, simd, depths,
                   gradient_labels);
}

int RegionAlignmentPx(const FeatureOptions& features) {
  const int top = features.pyramid_levels - 1;
  return std::max(features.spread_px.at(static_cast<std::size_t>(top)), 1) << top;
}

PreparedRegion PrepareSceneRegion(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                                  const PinholeCamera& camera, const FeatureOptions& features,
                                  const cv::Rect& region, SimdPath simd) {
  const int align = RegionAlignmentPx(features);
  const cv::Rect image(0, 0, color_bgr.cols, color_bgr.rows);
  const cv::Rect clipped = region & image;
  const auto up = [align](int value) { return (value + align - 1) / align * align; };
  const cv::Rect aligned = cv::Rect(cv::Point(clipped.x / align * align, clipped.y / align * align),
                                    cv::Point(up(clipped.br().x), up(clipped.br().y))) &
                           image;
  PreparedRegion result;
  if (aligned.empty()) return result;
  result.region_px = aligned;
  const cv::Mat depth = depth_mm.empty() ? cv::Mat() : depth_mm(aligned);
  result.scene = PrepareAt(color_bgr(aligned), depth, camera, aligned.tl(), features, simd,
                           result.depth_levels_mm, result.gradient_labels);
  if (depth.empty()) result.depth_levels_mm.clear();
  return result;
}

}  // namespace layermod
