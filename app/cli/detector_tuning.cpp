// SPDX-License-Identifier: MIT
#include "cli/detector_tuning.h"

namespace layermod::cli {

void DetectorTuning::ApplyTo(DetectorOptions& options) const {
  options.coarse.upper_factor = edge_upper;
  options.match.max_refinements = refinements;
}

void AddDetectorTuningOptions(CLI::App* command, DetectorTuning& tuning) {
  command
      ->add_option("--edge-upper", tuning.edge_upper,
                   "Coarse positioning keeps a point with at most this many times the layer's "
                   "largest template depth-edge count (the paper uses 1.5)")
      ->check(CLI::Range(0.8f, 100.0f))
      ->capture_default_str();
  command
      ->add_option("--refinements", tuning.refinements,
                   "Top-level matches refined down the pyramid per object and frame, best first")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

}  // namespace layermod::cli
