// SPDX-License-Identifier: MIT
// Fuzz target: training-profile files (`layermod train --profile`, the studio's Load profile).
// A loaded profile must be valid, survive a JSON round trip unchanged and plan its views (or
// refuse them with an Error) as training does.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input.h"
#include "geometry/views.h"
#include "templates/training_profile.h"
#include "util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace layermod;
  fuzz::QuietLogsOnce();
  const auto path = fuzz::WriteScratchFile("profile.json", fuzz::AsText(data, size));
  TrainingProfile profile;
  try {
    profile = LoadTrainingProfile(path);
  } catch (const Error& error) {
    fuzz::AbortUnlessNamed(error, path.string());
    return 0;
  }
  profile.Validate();  // throws (a finding) if loading let an invalid profile through
  if (ToJson(TrainingProfileFromJson(ToJson(profile))) != ToJson(profile)) std::abort();
  try {
    SampleViews(profile.views);
  } catch (const Error&) {
    // Refusing a view grid too large to plan is an accepted outcome.
  }
  return 0;
}
