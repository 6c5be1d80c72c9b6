// SPDX-License-Identifier: MIT
// Occlusion-aware matching. Scene points nearer to the camera than any surface of the object can
// be (at the depth layer a template set was trained for) belong to an occluder. A template whose
// features fall on one has not failed to match there: those features are neither matched nor
// missed.
//
// Where templates are ranked (scored on the grid of their top pyramid level), a feature on an
// occluder scores at least kHiddenFeatureScore whatever its orientation: half a match, so that a
// partly hidden part still reaches the refinements while a template lying over an occluder
// alone ranks below the right matches in full view. Hits are refined on the scene as it is, and
// at level 0 the features on occluders are counted out: a match's similarity is that of its
// visible features, and it needs MatchOptions::min_visible_share of them
// (RawMatch::visible_share). Pixels past the image's border (a part the border cuts) are hidden
// in the same way.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "features/feature.h"
#include "match/matcher.h"
#include "match/scene_level.h"

namespace layermod {

// Of kMaxFeatureScore. With 3 of 4 (about what the visible features of a right template score)
// templates lying over a near object of the clutter, or reaching far past the image's border
// with a straight edge inside, crowded the refinements and the pose candidates (docs/NOTES.md).
inline constexpr int kHiddenFeatureScore = 2;

// What a search with occluders needs (TemplateSearch::occluders).
struct Occluders {
  std::vector<cv::Mat> masks;  // per level, CV_8UC1 of its size, non-zero at occluder pixels
  int hidden_credit = kHiddenFeatureScore;  // what a hidden feature scores where ranked
  // Level-0 pixels known to hold no hidden pixel (empty: none known): a match within them is
  // scored as without occluders.
  cv::Rect clear_px;
  // The scene templates are ranked on: above level 0, its linear memories score at least
  // `hidden_credit` at occluder pixels for every feature (its response maps, which only
  // refinement reads, are the scene's); level 0 (the top level only of templates without
  // coarser features) as the scene is. Shared by the searches made WithLevelZeroMask.
  std::shared_ptr<const PreparedScene> ranked;
};

// Throws Error unless there is one mask per level of `scene`, CV_8UC1 of that level's size, and
// the credit lies in 0..kMaxFeatureScore.
Occluders MakeOccluders(const PreparedScene& scene, std::vector<cv::Mat> masks,
                        int hidden_credit = kHiddenFeatureScore, const cv::Rect& clear_px = {});

// `shared` with `level0_mask` as the pixels counted out at level 0: ranked on `shared`'s copy of
// the scene (no copy is made), the features refined at level 0 judged by a mask of their own.
// Throws Error unless the mask is CV_8UC1 of the size of `shared`'s level-0 mask.
Occluders WithLevelZeroMask(const Occluders& shared, cv::Mat level0_mask);

// A template level's features whose modality the scene has, at one position, split by an
// occluder mask.
struct VisibleScore {
  int features = 0;  // usable features
  int hidden = 0;    // on an occluder pixel
  int sum = 0;       // the scene's responses at the others (kMaxFeatureScore each at most)

  int Visible() const { return features - hidden; }
};

// VisibleScore of `level` with its top-left at `top_left_px` in `scene`, whose responses at all
// the usable features sum to `sum_of_all` (what refinement scored there): only the features on
// occluders are read back and taken off. `occluders`: CV_8UC1 of the scene level's size,
// non-zero at occluder pixels. Features outside the scene count as visible and score nothing.
// Throws Error for a mask of another size or type.
VisibleScore ScoreVisibleFeatures(const TemplateLevel& level, const SceneLevel& scene,
                                  const cv::Mat& occluders, const cv::Point& top_left_px,
                                  int sum_of_all);

}  // namespace layermod
