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
      const cv::Mat normals =
          ComputeDepthNormals(depths[level], PyramidLevelCamera(camera, static_cast<int>(level)),
                              cv::Point(offset_px.x / scale, offset_px.y / scale),
                              features.max_normal_depth_step_mm, features.normal_frame);
      maps[ModalityIndex(Modality::kDepthNormal)] = QuantizeNormals(normals);
    }
  });
  return quantized;
}

// Level `level` of an image whose level 0 lies at `at` in a region (`at` a multiple of every
// level's scale), placed in that level of the region (`size`): zero everywhere else.
cv::Mat PadToRegion(const cv::Mat& image, cv::Size size, cv::Point at, int level) {
  if (image.empty()) return image;
  cv::Mat padded = cv::Mat::zeros(size, image.type());
  image.copyTo(padded(cv::Rect(cv::Point(at.x >> level, at.y >> level), image.size())));
  return padded;
}

int FloorToMultiple(int value, int step) {
  return (value >= 0 ? value : value - step + 1) / step * step;
}

int CeilToMultiple(int value, int step) { return FloorToMultiple(value + step - 1, step); }

// Per pyramid level, CV_8UC1 of that level's size: non-zero at the pixels of the padding, those
// whose level-0 pixel lies outside `image` (given in the region's level-0 pixels). Level k + 1's
// pixel u stands for level k's pixel 2u, which is what DownsampleNearest keeps.
std::vector<cv::Mat> OutsideImageMasks(cv::Size size, int levels, const cv::Rect& image) {
  std::vector<cv::Mat> masks;
  masks.reserve(static_cast<std::size_t>(levels));
  cv::Mat mask(size, CV_8UC1, cv::Scalar(255));
  mask(image & cv::Rect(cv::Point(0, 0), size)).setTo(0);
  for (int level = 0; level < levels; ++level) {
    masks.push_back(level == 0 ? mask : DownsampleNearest(masks.back()));
  }
  return masks;
}

}  // namespace

PreparedScene PrepareScene(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                           const PinholeCamera& camera, const FeatureOptions& features,
                           SimdPath simd) {
  std::vector<cv::Mat> depths;
  return PreparedScene(QuantizeAt(color_bgr, depth_mm, camera, cv::Point(0, 0), features, depths),
                       features.spread_px, simd);
}

int RegionAlignmentPx(const FeatureOptions& features) {
  const int top = features.pyramid_levels - 1;
  return std::max(features.spread_px.at(static_cast<std::size_t>(top)), 1) << top;
}

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
    result.outside_image =
        OutsideImageMasks(aligned.size(), features.pyramid_levels, image - aligned.tl());
    const cv::Point at = seen.tl() - aligned.tl();
    for (std::size_t level = 0; level < quantized.size(); ++level) {
      const cv::Size size = result.outside_image[level].size();
      const int k = static_cast<int>(level);
      for (cv::Mat& labels : quantized[level]) labels = PadToRegion(labels, size, at, k);
      result.depth_levels_mm[level] = PadToRegion(result.depth_levels_mm[level], size, at, k);
    }
  }
  result.gradient_labels = quantized[0][ModalityIndex(Modality::kColorGradient)];
  result.scene = PreparedScene(quantized, features.spread_px, simd);
  if (depth.empty()) result.depth_levels_mm.clear();
  return result;
}

}  // namespace layermod
