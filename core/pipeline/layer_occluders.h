// SPDX-License-Identifier: MIT
// Which scene points occlude an object matched with the templates of one depth layer
// (occlusion-aware matching, match/occluders.h): those nearer than any surface of the object
// can be while those templates fit it.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace layermod {

// A layer's templates fit an object whose sphere centre lies within half a layer step (at most
// half a sphere radius, paper §3.1) of the layer depth; its surface is at most one radius nearer
// than its centre. A margin of 2 % of the depth covers the sensor's noise.
double NearestSurfaceMm(double layer_depth_mm, double sphere_radius_mm);

// PreparedRegion::depth_levels_mm in whole millimetres (CV_16U; rounded, negative and NaN
// become 0 = no depth), once per frame for all the comparisons below.
std::vector<cv::Mat> WholeMillimetreDepths(const std::vector<cv::Mat>& depth_levels_mm);

// Per pyramid level of `depth_levels_mm` (WholeMillimetreDepths), CV_8UC1, non-zero where the
// depth is valid and nearer than `nearest_surface_mm`, looked at only within `reach_px`
// (level-0 region pixels: where the templates of a search can put features); empty when no
// pixel is (or without depth).
std::vector<cv::Mat> OccludersNearerThan(const std::vector<cv::Mat>& depth_levels_mm,
                                         double nearest_surface_mm, const cv::Rect& reach_px);

}  // namespace layermod
