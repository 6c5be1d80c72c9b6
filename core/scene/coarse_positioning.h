// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "scene/region_division.h"

namespace layermod {

// Coarse positioning by depth edges (paper §3.3, Eq. 2-5, Table 2; docs/ARCHITECTURE.md).
struct CoarsePositioningOptions {
  int point_step_px = 8;      // s: spacing of detection points inside a block
  float lower_factor = 0.8f;  // keep when lower_factor * N_min <= num_i ...
  // ... <= upper_factor * N_max. The paper's 1.5 rejects parts standing among clutter or
  // behind an occluder, whose outlines add to num_i: on four synthetic scene sets (330 targets,
  // four objects) 2.0 found 6 more targets than 1.5 and lost none.
  float upper_factor = 2.0f;
  // Keep the blocks with most surviving points. The paper keeps 1; in clutter the part's block
  // is often second to eighth (other objects of similar size, the table's far edge pass the edge
  // test too, and a flat part lying on the table shares its depth band's block): 5 found 5 more
  // of 80 targets over 8 objects than 3; 8 found 21 more of 1,335 than 5 on eight scene sets,
  // for 2-4 % more time (docs/RESULTS.md, "Eight scene blocks").
  int max_blocks = 8;
  int hole_fill_px = 8;  // sensor holes up to this wide are filled from the far side
                         // before edges are counted (see FillDepthHolesFromFar)

  void Validate() const;  // throws Error
};

// Extreme depth-edge counts of the templates of one layer (N_min, N_max); a layer without
// usable templates has `valid == false` and its blocks are skipped.
struct LayerEdgeRange {
  int n_min = 0;
  int n_max = 0;
  bool valid = false;
};

struct DetectionPoint {
  cv::Point pixel;
  float depth_mm = 0.0f;
  float edge_count = 0.0f;  // num_i, scaled to the template size L
  bool kept = false;
};

struct BlockCandidates {
  int block_index = 0;  // into RegionDivision::blocks
  std::vector<DetectionPoint> points;
  int kept_count = 0;
};

struct CoarsePositioning {
  std::vector<BlockCandidates> evaluated;  // every block that had a valid layer
  std::vector<int> kept;                   // indices into `evaluated`, best first

  // The surviving detection points of the kept blocks.
  std::vector<DetectionPoint> KeptPoints() const;
};

// Evaluates detection points on a step-s grid in every block. At a point of depth z_i the object
// spans l_i = f*R/z_i pixels (Eq. 2), the template L = f*R/D (Eq. 3); the depth edges counted in
// the l_i x l_i window are scaled by L / l_i = z_i / D (Eq. 4: edges are curves, so their pixel
// count scales linearly) and compared with the layer's template counts (Eq. 5).
// `edge_mask`: CV_8U depth edges of the scene (same threshold as training).
CoarsePositioning PositionCoarsely(const RegionDivision& division, const cv::Mat& depth_mm,
                                   const cv::Mat& edge_mask, double focal_px, double diameter_mm,
                                   const std::vector<LayerEdgeRange>& edge_ranges,
                                   const CoarsePositioningOptions& options = {});

}  // namespace layermod
