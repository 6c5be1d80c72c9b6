// SPDX-License-Identifier: MIT
// The detector settings `layermod detect`, `eval` and `bench` all take on the command line.
#pragma once

#include <CLI/CLI.hpp>

#include "pipeline/detector.h"

namespace layermod::cli {

struct DetectorTuning {
  float edge_upper = CoarsePositioningOptions{}.upper_factor;  // paper Eq. 5's upper factor
  int refinements = MatchOptions{}.max_refinements;            // the matcher's budget

  void ApplyTo(DetectorOptions& options) const;
};

// --edge-upper --refinements.
void AddDetectorTuningOptions(CLI::App* command, DetectorTuning& tuning);

}  // namespace layermod::cli
