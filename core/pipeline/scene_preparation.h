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

// The same for a part of the capture only: `region` (level-0 pixels) is grown to the alignment
// of RegionAlignmentPx and clipped to the image, then prepared as if it were the whole image,
// with the normals computed for its true place in the camera. Matches found in it are at
// `region_px.tl()` from the capture's pixels. Away from its border (a few pixels of image
// filtering) every level is the same as the whole capture's.
struct PreparedRegion {
  PreparedScene scene;
  cv::Rect region_px;  // the part prepared; empty when `region` missed the image
  // The region's depth at each pyramid level (nearest-neighbour downsampling), the size of
  // that level's scene: CV_32F mm, 0 = no depth; empty without depth.
  std::vector<cv::Mat> depth_levels_mm;
  // Where the region reaches past the image (PrepareSceneRegion's padding): per pyramid level,
  // CV_8UC1 of that level's size, non-zero at padding pixels, which carry no label. Empty when the
  // region lies inside the image.
  std::vector<cv::Mat> outside_image;
  // The region's colour-gradient labels at level 0 before spreading (QuantizeColorGradients):
  // what verification compares a pose's outline with.
  cv::Mat gradient_labels;
};
// With `padding_px` > 0 the region may reach that far past the image (rounded up to the
// alignment), so that templates of a part the image's border cuts can be placed over it: the
// padding has no labels and no depth, and PreparedRegion::outside_image marks it.
PreparedRegion PrepareSceneRegion(const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                                  const PinholeCamera& camera, const FeatureOptions& features,
                                  const cv::Rect& region, SimdPath simd = SimdPath::kAuto,
                                  int padding_px = 0);

// The alignment of prepared regions: one top-level grid cell of the coarsest level (spread T
// there times 2^level), so that the region's pyramid and grid line up with the whole image's.
int RegionAlignmentPx(const FeatureOptions& features);

}  // namespace layermod
