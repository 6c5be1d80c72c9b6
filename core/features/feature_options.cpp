// SPDX-License-Identifier: MIT
#include "features/feature_options.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace layermod {

std::string_view NormalFrameName(NormalFrame frame) {
  return frame == NormalFrame::kCamera ? "camera" : "viewing_ray";
}

std::optional<NormalFrame> NormalFrameFromName(std::string_view name) {
  if (name == "camera") return NormalFrame::kCamera;
  if (name == "viewing_ray") return NormalFrame::kViewingRay;
  return std::nullopt;
}

void FeatureOptions::Validate() const {
  if (color_features < 0 || normal_features < 0 || color_features + normal_features == 0) {
    throw Error("features: need a positive number of colour and/or normal features");
  }
  if (color_features > 8191 || normal_features > 8191) {
    throw Error("features: at most 8191 features per modality");
  }
  if (min_features < 1) throw Error("features: min_features must be at least 1");
  if (!(weak_gradient > 0.0f) || !(strong_gradient >= weak_gradient)) {
    throw Error("features: need 0 < weak_gradient <= strong_gradient");
  }
  if (!(max_normal_depth_step_mm > 0.0f)) {
    throw Error("features: max_normal_depth_step_mm must be positive");
  }
  if (pyramid_levels < 1 || pyramid_levels > 4) {
    throw Error("features: pyramid_levels must be 1..4");
  }
  if (static_cast<int>(spread_px.size()) != pyramid_levels) {
    throw Error("features: spread_px needs one value per pyramid level");
  }
  for (int spread : spread_px) {
    if (spread < 1 || spread > 16) throw Error("features: spread_px values must be 1..16");
  }
  if (!(depth_edge_fraction > 0.0f) || !std::isfinite(depth_edge_fraction)) {
    throw Error("features: depth_edge_fraction must be positive");
  }
}

}  // namespace layermod
