// SPDX-License-Identifier: MIT
// LineMOD's scattered feature selection.
#pragma once

#include <cstdint>
#include <vector>

#include "features/feature.h"

namespace layermod {

// A pixel that could become a feature: its position (any frame), label 0..7 and a score (higher is
// better: gradient magnitude, or distance from label and mask borders for normals).
struct FeatureCandidate {
  int x = 0;
  int y = 0;
  std::uint8_t label = 0;
  float score = 0.0f;
};

// Chooses up to `count` candidates spread over the object (LineMOD's scattered selection).
// Candidates are ordered by score (descending; ties by y, then x, then label, so the result does
// not depend on the input order), then kept greedily, in passes over the candidates not kept yet,
// when no kept feature lies closer than a distance d. d starts at sqrt(area / count), the grid
// spacing of `count` points over the candidates' bounding box, and shrinks after each pass by
// 10 % (at least 1 px), or further when no waiting candidate would be kept at the shrunk
// distance, until `count` features are kept. Fewer candidates than `count` are all returned, in
// score order. Positions must fit in int16 (Feature); throws Error otherwise.
std::vector<Feature> SelectScatteredFeatures(std::vector<FeatureCandidate> candidates, int count,
                                             Modality modality);

}  // namespace layermod
