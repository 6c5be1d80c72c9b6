// SPDX-License-Identifier: MIT
#pragma once

// How likely a detection's pose is right, 0..1: a logistic model over what the pipeline already
// measured (the LineMOD score, the depth fit and how much of the silhouette the scene explains,
// occludes or contradicts, the surface continuing past the outline, colour, ICP). Fitted on the
// project's own synthetic scene sets (right poses against wrong poses and detections of absent
// parts); the coefficients and the command that reproduces them are in confidence.cpp.

#include <array>
#include <string_view>

#include "pipeline/detector.h"

namespace layermod {

// The model's inputs, each scaled to about 0..1.
struct ConfidenceFeatures {
  static constexpr int kCount = 11;
  std::array<double, kCount> values{};

  static std::array<std::string_view, kCount> Names();
};

ConfidenceFeatures FeaturesOf(const Detection& detection);

// With depth, the full model: how likely the pose is right (ADD(-S) <= 0.1 d). Without depth
// (colour-only captures) one over the score and colour: how likely the detection is right in
// the image; LINE-2D alone rarely is on cluttered scenes, so these confidences are low.
double DetectionConfidence(const ConfidenceFeatures& features, bool has_depth);

}  // namespace layermod
