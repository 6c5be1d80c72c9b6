// SPDX-License-Identifier: MIT
// Depth edges for coarse positioning (paper §3.3: Sobel on depth above 30 % of eta, Eq. 5).
#pragma once

#include <opencv2/core.hpp>

namespace layermod {

// Depth-edge pixels of a CV_32F depth map in mm: 255 where the 3x3 Sobel magnitude divided by 4
// exceeds `threshold_mm` (so a step of D mm between neighbouring pixels gives a magnitude of
// about D; a smooth slope of s mm per pixel measures 2 s), 0 elsewhere. Both sides of a step
// respond, so a silhouette gives a band about 2-3 px wide. A pixel whose 3x3 window (replicated at
// the image border) contains an invalid depth (<= 0, NaN or inf) is never an edge: invalid depth is
// neither near nor far. Returns CV_8U of the same size. Throws Error for another type or a
// non-positive threshold.
cv::Mat DepthEdgeMask(const cv::Mat& depth_mm, float threshold_mm);
// The two halves of DepthEdgeMask, for a frame searched with several thresholds: the Sobel
// magnitude divided by 4 (CV_32F; -1 where the 3x3 window holds an invalid depth), then the
// mask of a threshold on it.
cv::Mat DepthEdgeStrength(const cv::Mat& depth_mm);
cv::Mat DepthEdgeMaskFromStrength(const cv::Mat& strength, float threshold_mm);

// Depth sensors leave holes along depth discontinuities (shadows, flying pixels removed), right
// where the edges are. Fills each invalid pixel with the farthest valid depth within
// `max_gap_px` (a hole at a discontinuity belongs to the background side), so the step survives
// for DepthEdgeMask; the inside of larger holes stays invalid. CV_32F mm in and out.
cv::Mat FillDepthHolesFromFar(const cv::Mat& depth_mm, int max_gap_px);

// Number of depth-edge pixels (see DepthEdgeMask).
int CountDepthEdges(const cv::Mat& depth_mm, float threshold_mm);

}  // namespace layermod
