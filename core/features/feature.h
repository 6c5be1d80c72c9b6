// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

namespace layermod {

enum class Modality : std::uint8_t {
  kColorGradient = 0,  // quantized gradient orientation of the strongest colour channel
  kDepthNormal = 1,    // quantized surface normal from depth
};

// One LineMOD feature: position relative to the template's top-left corner at its pyramid level,
// and a quantized label 0..7 (one of 8 orientation bins).
struct Feature {
  std::int16_t x = 0;
  std::int16_t y = 0;
  std::uint8_t label = 0;
  Modality modality = Modality::kColorGradient;

  bool operator==(const Feature&) const = default;
};

// The features of one template at one pyramid level (level 0 = full resolution, level k = 1/2^k).
// width/height: the template box at that level (bounding box of its features).
struct TemplateLevel {
  int pyramid_level = 0;
  int width = 0;
  int height = 0;
  std::vector<Feature> features;

  bool operator==(const TemplateLevel&) const = default;
};

}  // namespace layermod
