// SPDX-License-Identifier: MIT
#pragma once

// Options of the synthetic RGB-D scene generator (`layermod synth`).

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "geometry/camera.h"

namespace layermod {

// A Kinect-like structured-light sensor (Nguyen et al. 2012 for the axial noise; Khoshelham and
// Elberink 2012 for the disparity quantisation).
struct SensorNoiseOptions {
  bool enabled = true;
  // Axial noise sigma(z) = base + quadratic * ((z - reference) / 1000 mm)^2.
  double sigma_base_mm = 1.2;
  double sigma_quadratic_mm = 1.9;
  double sigma_reference_mm = 400.0;
  // Depth comes from disparity d = f * baseline / z measured in 1/subpixel steps.
  double baseline_mm = 75.0;
  double disparity_subpixel = 8.0;
  // Outside this range the sensor returns nothing.
  double min_range_mm = 400.0;
  double max_range_mm = 4000.0;
  // Depth is lost in a band of 1..edge_band_max_px pixels around jumps larger than edge_jump_mm
  // at 1 m (proportional to depth), in patches covering about edge_drop_probability of the band.
  double edge_jump_mm = 20.0;
  int edge_band_max_px = 3;
  double edge_drop_probability = 0.5;
  // Up to this many small blobs without depth (dark or specular spots), radius up to max.
  int holes_max = 6;
  int hole_radius_max_px = 6;
  // Colour: slight optical blur, then Gaussian noise (levels of 0..255).
  double color_blur_sigma_px = 0.6;
  double color_noise_sigma = 3.0;

  void Validate() const;  // throws Error
};

struct SynthOptions {
  // BOP models folder: obj_NNNNNN.ply (+ models_info.json); or one PLY file (one object id).
  std::filesystem::path models_dir;
  std::vector<std::int32_t> obj_ids;  // targets, one per image, cycled
  int scenes = 10;                    // images to generate
  std::uint64_t seed = 1;             // same seed, same dataset (whatever the thread count)
  // Distance from the camera to the target's circumscribing-sphere centre.
  double dmin_mm = 650.0;
  double dmax_mm = 1150.0;
  // Camera on the upper hemisphere of the table (the evaluation envelope; training covers it
  // with TrainingProfile::DefaultEnvelopeViews).
  double elevation_min_deg = 10.0;
  double elevation_max_deg = 88.0;
  double roll_max_deg = 45.0;
  // Clutter: 1..clutter other models of models_dir and 1..clutter primitives (0: none).
  int clutter = 3;
  double min_target_visibility = 0.6;  // of the target's silhouette pixels
  // Below 1, every image insists on a partly hidden target: clutter is laid out again, and if
  // nothing standing on the table hides enough (cameras high above), an occluder is placed in
  // the line of sight.
  double max_target_visibility = 1.0;
  int instances = 1;             // copies of the target in each image (1..5), all annotated
  double absent_fraction = 0.0;  // share of images without the target: clutter only
  double max_tilt_deg = 3.0;     // objects stand upright, give or take this
  // The models' up axis (geometry/up_axis.h): they stand with it pointing up. Identity: +Z.
  Eigen::Matrix3d upright_from_model = Eigen::Matrix3d::Identity();
  // Models lie in any orientation (uniform over all rotations) instead of upright.
  bool any_orientation = false;
  int margin_px = 4;                      // the whole target stays this far inside the image
  std::filesystem::path backgrounds_dir;  // photos textured onto the table; empty: procedural
  PinholeCamera camera;
  std::filesystem::path out_dir;  // the BOP dataset root to create (absent or empty)
  int threads = 0;                // 0: all cores
  SensorNoiseOptions noise;

  // Throws Error naming the option (no file access; SynthesizeScenes checks the folders).
  void Validate() const;
};

}  // namespace layermod
