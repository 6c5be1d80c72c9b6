// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "features/feature.h"
#include "geometry/pose.h"
#include "geometry/views.h"

namespace layermod {

enum class TemplateStatus : std::uint8_t {
  kOk = 0,
  kTooFewFeatures = 1,  // kept in the table so ids never shift; skipped by the matcher
};

// One trained template with all its metadata in the same record.
struct TemplateRecord {
  std::uint32_t id = 0;  // index in the archive's template table
  std::int32_t obj_id = 0;
  std::uint16_t layer_index = 0;
  float layer_depth_mm = 0.0f;
  ViewAngles view;
  Pose cam_from_model;                   // pose of the rendered view (sphere centre at layer depth)
  cv::Rect bbox_px;                      // level-0 template box in the training camera's pixels
  cv::Point2f centre_offset_px;          // projected sphere centre relative to bbox_px.tl()
  float centre_minus_surface_mm = 0.0f;  // sphere centre depth minus median surface depth
  std::int32_t depth_edge_count = 0;     // coarse-positioning count (paper §3.3, Table 2)
  TemplateStatus status = TemplateStatus::kOk;
  std::vector<TemplateLevel> levels;  // pyramid, level 0 first

  int FeatureCount() const {
    return levels.empty() ? 0 : static_cast<int>(levels[0].features.size());
  }
};

}  // namespace layermod
