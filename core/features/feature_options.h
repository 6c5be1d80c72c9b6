// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "features/normal_frame.h"

namespace layermod {

// Parameters of LineMOD feature extraction, stored in the archive so detection uses the same.
struct FeatureOptions {
  int color_features = 63;        // colour-gradient features per template at level 0
  int normal_features = 63;       // depth-normal features per template at level 0
  int min_features = 16;          // fewer (both modalities, level 0) flags the template as weak
  float weak_gradient = 10.0f;    // gradient magnitude below which a pixel has no orientation
  float strong_gradient = 55.0f;  // gradient magnitude a colour feature candidate must exceed
  float max_normal_depth_step_mm = 50.0f;  // depth differences beyond this are not surface
  int pyramid_levels = 2;                  // level k has 1/2^k resolution
  std::vector<int> spread_px = {5, 8};     // LineMOD's T per pyramid level (detection)
  // Depth-edge threshold for coarse positioning: this fraction of the object's largest bounding
  // box side (paper: 30 % of eta), compared with the depth step in mm between neighbours.
  float depth_edge_fraction = 0.3f;
  // The frame depth normals are quantized in, templates and scenes alike (features/normal_frame.h).
  NormalFrame normal_frame = NormalFrame::kViewingRay;

  void Validate() const;  // throws Error naming the bad field
  bool operator==(const FeatureOptions&) const = default;
};

}  // namespace layermod
