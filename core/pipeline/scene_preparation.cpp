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

using QuantizedLevels = std::vector<std::array<cv::Mat, kModalityCount>>;

// The scene's quantized pyramid (colour gradients; depth normals with depth); its depth levels
// into `depths` (empty Mats without depth).
QuantizedLevels QuantizeAt(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, cv::Point offset_px,
                           const FeatureOptions& features, std::vector<cv::Mat>& depths) {
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
  QuantizedLevels quantized(levels);
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
  return quantized;
}

// `image` (level 0 at `at` in a region of `size`, `at` a multiple of every level's scale) as the
// region's: zero everywhere else, at every level.
cv::Mat PadToRegion(const cv::Mat& image, cv::Size size, cv::Point at, int level) {
  if (image.empty()) return image;
  for (int k = 0; k < level; ++k) size = cv::Size((size.width + 1) / 2, (size.height + 1) / 2);
  const cv::Point offset(at.x >> level, at.y >> level);
  cv::Mat padded = cv::Mat::zeros(size, image.type());
  image.copyTo(padded(cv::Rect(offset, image.size())));
  return padded;
}

PreparedScene Prepared(const QuantizedLevels& quantized, const FeatureOptions& features,
                       SimdPath simd, cv::Mat& gradient_labels) {
  gradient_labels = quantized[0][ModalityIndex(Modality::kColorGradient)];
  return PreparedScene(quantized, features.spread_px, simd);
}

}  // namespace

PreparedScene PrepareScene(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, const FeatureOptions& features,
                           SimdPath simd) {
  std::vector<cv::Mat> depths;
  cv::Mat gradient_labels;
  return Prepared(QuantizeAt(color_bgr, depth_mm, camera, cv::Point(0, 0), features, depths),
                  features, simd, gradient_labels);
}

int RegionAlignmentPx(const FeatureOptions& features) {
  const int top = features.pyramid_levels - 1;
  return std::max(features.spread_px.at(static_cast<std::size_t>(top)), 1) << top;
}

namespace {

int FloorToMultiple(int value, int step) {
  return (value >= 0 ? value : value - step + 1) / step * step;
}

int CeilToMultiple(int value, int step) { return FloorToMultiple(value + step - 1, step); }

// Per pyramid level, CV_8UC1 of that level's size: non-zero at the pixels of the padding (those
// whose level-0 pixel lies outside `image`, given in the region's level-0 pixels).
std::vector<cv::Mat> OutsideImageMasks(cv::Size size, int levels, const cv::Rect& image) {
  std::vector<cv::Mat> masks;
  for (int level = 0; level < levels; ++level) {
    const int scale = 1 << level;
    if (level > 0) size = cv::Size((size.width + 1) / 2, (size.height + 1) / 2);
    const cv::Rect inside = cv::Rect(cv::Point(CeilToMultiple(image.x, scale) / scale,
                                               CeilToMultiple(image.y, scale) / scale),
                                     cv::Point(CeilToMultiple(image.br().x, scale) / scale,
                                               CeilToMultiple(image.br().y, scale) / scale)) &
                            cv::Rect(cv::Point(0, 0), size);
    cv::Mat mask(size, CV_8UC1, cv::Scalar(255));
    mask(inside).setTo(0);
    masks.push_back(mask);
  }
  return masks;
}

}  // namespace

PreparedRegion PrepareSceneRegion(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                                  const PinholeCamera& camera, const FeatureOptions& features,
                                  const cv::Rect& region, SimdPath simd, int padding_px) {
  const int align = RegionAlignmentPx(features);
  const cv::Rect image(0, 0, color_bgr.cols, color_bgr.rows);
  const int padding = CeilToMultiple(std::max(padding_px, 0), align);
  const cv::Rect reachable(-padding, -padding, image.width + 2 * padding,
                           image.height + 2 * padding);
  const cv::Rect clipped = region & reachable;
  const cv::Rect aligned =
      cv::Rect(
          cv::Point(FloorToMultiple(clipped.x, align), FloorToMultiple(clipped.y, align)),
          cv::Point(CeilToMultiple(clipped.br().x, align), CeilToMultiple(clipped.br().y, align))) &
      reachable;
  PreparedRegion result;
  if ((aligned & image).empty()) return result;
  result.region_px = aligned;
  const cv::Rect seen = aligned & image;
  const cv::Mat depth = depth_mm.empty() ? cv::Mat() : depth_mm(seen);
  QuantizedLevels quantized =
      QuantizeAt(color_bgr(seen), depth, camera, seen.tl(), features, result.depth_levels_mm);
  if (seen != aligned) {
    // Past the image there is nothing: no labels, no depth. The image's part is quantized as it
    // would be alone, then placed in the region (its corner lies on every level's grid).
    const cv::Point at = seen.tl() - aligned.tl();
    for (std::size_t level = 0; level < quantized.size(); ++level) {
      for (cv::Mat& labels : quantized[level]) {
        labels = PadToRegion(labels, aligned.size(), at, static_cast<int>(level));
      }
      result.depth_levels_mm[level] =
          PadToRegion(result.depth_levels_mm[level], aligned.size(), at, static_cast<int>(level));
    }
    result.outside_image =
        OutsideImageMasks(aligned.size(), features.pyramid_levels, image - aligned.tl());
  }
  result.scene = Prepared(quantized, features, simd, result.gradient_labels);
  if (depth.empty()) result.depth_levels_mm.clear();
  return result;
}

}  // namespace layermod
