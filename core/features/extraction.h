// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "features/feature.h"
#include "features/feature_options.h"
#include "geometry/camera.h"
#include "render/rasterizer.h"

namespace layermod {

// The LineMOD features of one rendered view, over all pyramid levels.
struct ExtractedTemplate {
  // Level-0 bounding box of the features, in camera pixels. Level k's features are relative to
  // (bbox_px.x >> k, bbox_px.y >> k).
  cv::Rect bbox_px;
  std::vector<TemplateLevel> levels;  // one per pyramid level, level 0 first

  int FeatureCount(int level = 0) const;
};

// Extracts colour-gradient features on the object's silhouette and interior edges and
// depth-normal features in its interior (normals from depth with the real intrinsics), scattered
// over the object, at every pyramid level. A view with too few candidates yields fewer features;
// the caller decides whether the template is weak (FeatureOptions::min_features).
ExtractedTemplate ExtractTemplate(const RenderedView& view, const PinholeCamera& camera,
                                  const FeatureOptions& options);

}  // namespace layermod
