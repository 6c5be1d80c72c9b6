// SPDX-License-Identifier: MIT
#include "synth/synth_options.h"

#include <cmath>
#include <sstream>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

void Require(bool condition, const std::string& message) {
  if (!condition) throw Error("synth options: " + message);
}

bool Finite(double value) { return std::isfinite(value); }

std::string Mm(double value) {
  std::ostringstream text;
  text << value << " mm";
  return text.str();
}

}  // namespace

void SensorNoiseOptions::Validate() const {
  Require(Finite(sigma_base_mm) && Finite(sigma_quadratic_mm) && Finite(sigma_reference_mm) &&
              sigma_base_mm >= 0.0 && sigma_quadratic_mm >= 0.0,
          "depth noise sigmas must be finite and not negative");
  Require(Finite(baseline_mm) && baseline_mm > 0.0, "sensor baseline must be positive");
  Require(Finite(disparity_subpixel) && disparity_subpixel >= 1.0,
          "disparity subpixel steps must be at least 1");
  Require(Finite(min_range_mm) && Finite(max_range_mm) && min_range_mm >= 0.0 &&
              min_range_mm < max_range_mm,
          "sensor range must satisfy 0 <= min < max");
  Require(Finite(edge_jump_mm) && edge_jump_mm > 0.0, "edge jump must be positive");
  Require(edge_band_max_px >= 0 && edge_band_max_px <= 16, "edge band must be 0..16 pixels");
  Require(edge_drop_probability >= 0.0 && edge_drop_probability <= 1.0,
          "edge drop probability must be in [0, 1]");
  Require(holes_max >= 0 && hole_radius_max_px >= 1, "holes: count >= 0 and radius >= 1 px");
  Require(Finite(color_blur_sigma_px) && color_blur_sigma_px >= 0.0 && Finite(color_noise_sigma) &&
              color_noise_sigma >= 0.0,
          "colour blur and noise must not be negative");
}

void SynthOptions::Validate() const {
  Require(!obj_ids.empty(), "give at least one target object id");
  for (const std::int32_t id : obj_ids) {
    Require(id > 0, "object ids must be positive (got " + std::to_string(id) + ")");
  }
  Require(scenes > 0, "the number of scenes must be positive (got " + std::to_string(scenes) + ")");
  Require(Finite(dmin_mm) && Finite(dmax_mm) && dmin_mm > 0.0,
          "distances must be positive finite numbers");
  Require(dmin_mm < dmax_mm,
          "dmin (" + Mm(dmin_mm) + ") must be less than dmax (" + Mm(dmax_mm) + ")");
  Require(elevation_min_deg >= 0.0 && elevation_min_deg <= elevation_max_deg &&
              elevation_max_deg <= 89.0,
          "elevation must satisfy 0 <= min <= max <= 89 degrees");
  Require(roll_max_deg >= 0.0 && roll_max_deg <= 180.0, "roll must be 0..180 degrees");
  Require(clutter >= 0 && clutter <= 5,
          "clutter must be 0..5 (got " + std::to_string(clutter) + ")");
  Require(min_target_visibility >= 0.0 && min_target_visibility <= 1.0,
          "minimum target visibility must be in [0, 1]");
  Require(max_target_visibility >= min_target_visibility && max_target_visibility <= 1.0,
          "maximum target visibility must be in [minimum, 1]");
  Require(instances >= 1 && instances <= 5,
          "instances must be 1..5 (got " + std::to_string(instances) + ")");
  Require(absent_fraction >= 0.0 && absent_fraction <= 1.0,
          "the share of images without the target must be in [0, 1]");
  Require(max_tilt_deg >= 0.0 && max_tilt_deg <= 30.0, "tilt must be 0..30 degrees");
  Require(margin_px >= 0, "margin must not be negative");
  Require(threads >= 0, "threads must not be negative");
  Require(!models_dir.empty(), "a models folder is required");
  Require(!out_dir.empty(), "an output folder is required");
  try {
    camera.Validate();
  } catch (const Error& error) {
    throw Error(std::string("synth options: ") + error.what());
  }
  noise.Validate();
}

}  // namespace layermod
