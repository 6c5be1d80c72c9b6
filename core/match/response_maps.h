// SPDX-License-Identifier: MIT
// Stage 2 of LineMOD matching (PAMI 2012, §2.4): precomputed response maps, one per template
// orientation, so that scoring a feature is a single memory read.
#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "match/simd.h"

namespace layermod {

inline constexpr int kOrientationCount = 8;
// Score of a feature whose orientation the scene shows exactly (LineMOD's integer similarity).
inline constexpr int kMaxFeatureScore = 4;

// Similarity of template orientation `label` with scene orientation `scene_label` (both 0..7):
// kMaxFeatureScore for the same bin, 1 for an adjacent bin, 0 otherwise. Adjacency is circular
// (7 and 0 are neighbours): gradient bins cover 180 deg, sign ignored, and normal bins cover the
// 360 deg of (nx, ny) directions, so both modalities wrap around.
int OrientationSimilarity(int label, int scene_label);

// The best OrientationSimilarity of `label` with any orientation set in `bitmask` (0 for none).
int BitmaskSimilarity(int label, std::uint8_t bitmask);
// BitmaskSimilarity of `label` with every bitmask, indexed by the bitmask (256 entries): for
// loops over many pixels with one label, without a call per pixel.
const std::uint8_t* BitmaskSimilarityRow(int label);

// For each template orientation l: per pixel, BitmaskSimilarity(l, spread pixel). Computed with
// two 16-entry tables per orientation (low and high nibble of the bitmask, then max), which maps
// onto byte shuffles. Each returned map (CV_8UC1, size of `spread`) is a view into storage whose
// rows continue for at least kSimdBlock more bytes: the similarity kernels read whole blocks.
// `spread`: CV_8UC1 (empty in -> 8 empty maps). `path` selects the kernel (tests compare them).
std::array<cv::Mat, kOrientationCount> ComputeResponseMaps(const cv::Mat& spread,
                                                           SimdPath path = SimdPath::kAuto);

}  // namespace layermod
