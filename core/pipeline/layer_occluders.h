// SPDX-License-Identifier: MIT
// Which scene points occlude an object matched with the templates of one depth layer
// (occlusion-aware matching, match/occluders.h): those nearer than any surface of the object
// can be while those templates fit it.
#pragma once

#include <map>
#include <opencv2/core.hpp>
#include <optional>
#include <set>
#include <span>
#include <vector>

#include "match/occluders.h"
#include "pipeline/scene_preparation.h"

namespace layermod {

// A layer's templates fit an object whose sphere centre lies within half a layer step (at most
// half a sphere radius, paper §3.1) of the layer depth; its surface is at most one radius nearer
// than its centre. A margin of 2 % of the depth covers the sensor's noise.
double NearestSurfaceMm(double layer_depth_mm, double sphere_radius_mm);

// Layers share occluders: a layer's bound (NearestSurfaceMm) is rounded down to a multiple of
// kOccluderBoundStepMm, so that one ranked copy of the scene (match/occluders.h) serves every
// layer, of every object, whose bound rounds the same. Rounding down leaves out at most that
// much of what lies in front, never takes the object's own surface for an occluder. (One copy
// per layer, a frame of eight objects made up to 55 of them, a quarter of the frame's time.)
inline constexpr int kOccluderBoundStepMm = 100;
int SharedBoundMm(double layer_depth_mm, double sphere_radius_mm);  // <= 0: nothing is nearer

// One layer's search as occluders concern it: the layer's depth, the part's sphere radius, and
// where the search's templates can put features (level-0 region pixels).
struct LayerReach {
  double layer_depth_mm = 0.0;
  double sphere_radius_mm = 0.0;
  cv::Rect reach_px;
};

// The occluders of one frame's Scene-Patch searches: one shared entry per SharedBoundMm, each
// ranked on one copy of the scene for the whole prepared region (the padding past the image's
// border hidden as well).
class OccluderBank {
 public:
  OccluderBank() = default;  // nothing is an occluder (occlusion ignored)
  // The entries the searches `layers` need: those of the layers with something nearer than their
  // own bound (NearestSurfaceMm) within their reach; built side by side.
  OccluderBank(const PreparedRegion& prepared, std::span<const LayerReach> layers);

  // nullptr where nothing lies nearer than the bound, or for a bound not built.
  const Occluders* Find(int bound_mm) const;

  // The occluders of one layer's search: ranked on the shared entry of its SharedBoundMm, while
  // at level 0 the pixels nearer than its own bound and the padding are counted out (within the
  // reach; the level-0 mask is empty past it). nullopt where nothing lies nearer than its own
  // bound within its reach (its templates then read the scene as it is) or the entry is missing.
  std::optional<Occluders> ForLayer(const LayerReach& layer) const;

 private:
  // Whether a pixel nearer than the layer's own bound may lie within its reach: judged on the
  // cells of nearest_per_cell_mm_ the reach touches, so it may say yes for a pixel just past
  // the reach (a shared copy is then built that this layer does not use), never no for one in it.
  bool MayHaveNearerWithinReach(const LayerReach& layer) const;
  // CV_8UC1 of the level-0 size: within the reach, the pixels nearer than the layer's own bound
  // and the padding past the image; zero past the reach. Empty when no pixel within the reach
  // is nearer.
  cv::Mat LevelZeroMask(const LayerReach& layer) const;

  std::map<int, std::optional<Occluders>> by_bound_mm_;
  cv::Mat whole_mm_;             // the region's level-0 depth in whole millimetres (0: none)
  cv::Mat nearest_per_cell_mm_;  // whole_mm_'s nearest valid depth per cell (65535: none)
  cv::Mat outside_image_;        // level 0 of PreparedRegion::outside_image (empty: none)
};

}  // namespace layermod
