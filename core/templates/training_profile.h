// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "features/feature_options.h"
#include "geometry/views.h"

namespace layermod {

// Everything that decides which templates are trained. One struct feeds the CLI flags, the
// studio's form, the saved profile file and the archive's manifest.
struct TrainingProfile {
  double depth_min_mm = 500.0;
  double depth_max_mm = 1500.0;
  ViewSamplingOptions views = DefaultEnvelopeViews();
  FeatureOptions features;

  void Validate() const;  // throws Error naming the bad field

  // Covers the evaluation envelope (SynthOptions): upper hemisphere 0..90 deg evenly sampled,
  // in-plane roll -45..45 deg.
  static ViewSamplingOptions DefaultEnvelopeViews();
};

// Named view envelopes (relative to the model's up axis, which they keep):
//   "tabletop"  the part stands on its base: DefaultEnvelopeViews();
//   "full"      any orientation (bin picking): the whole view sphere evenly every 12 deg, roll
//               all round every 15 deg: 6,864 views per layer against tabletop's 1,001.
const std::vector<std::string>& ViewPresetNames();
// Throws Error for an unknown name.
ViewSamplingOptions ViewPreset(std::string_view name, const Eigen::Matrix3d& upright_from_model);

nlohmann::json ToJson(const TrainingProfile& profile);
TrainingProfile TrainingProfileFromJson(const nlohmann::json& json);  // throws FormatError

// Profile files (JSON). Save is atomic; Load throws IoError/FormatError naming the file.
void SaveTrainingProfile(const std::filesystem::path& path, const TrainingProfile& profile);
TrainingProfile LoadTrainingProfile(const std::filesystem::path& path);

}  // namespace layermod
