// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/pose.h"

namespace layermod {

// An inclusive angle grid `min:step:max` in degrees.
struct AngleRange {
  double min_deg = 0.0;
  double step_deg = 1.0;
  double max_deg = 0.0;

  void Validate(std::string_view name) const;  // throws Error naming the range
  std::vector<double> Values() const;
  std::size_t Count() const;     // Values().size(), without allocating
  std::string ToString() const;  // "min:step:max"
  static AngleRange Parse(std::string_view text, std::string_view name);  // throws Error
  bool operator==(const AngleRange&) const = default;
};

// Viewpoint on the sphere around the object: the camera sits at azimuth/elevation (measured in the
// object's upright frame, geometry/up_axis.h: +Z up, elevation from the XY plane), looks at the
// sphere centre, and is rolled about its optical axis.
struct ViewAngles {
  double azimuth_deg = 0.0;
  double elevation_deg = 0.0;
  double roll_deg = 0.0;
};

// Unit vector from the sphere centre towards the camera of a view (upright frame).
Eigen::Vector3d DirectionFromAngles(double azimuth_deg, double elevation_deg);

struct ViewSamplingOptions {
  AngleRange azimuth{0.0, 15.0, 345.0};
  AngleRange elevation{0.0, 15.0, 75.0};
  AngleRange roll{-45.0, 15.0, 45.0};
  // When > 0: sample camera directions evenly on the view sphere (Fibonacci lattice) with about
  // this angular spacing, limited to the elevation range, instead of the azimuth/elevation grid.
  double even_spacing_deg = 0.0;
  // The model's reference orientation (geometry/up_axis.h): the angles above are measured in the
  // frame this rotation takes the model to. Identity: the model's +Z is up.
  Eigen::Matrix3d upright_from_model = Eigen::Matrix3d::Identity();

  void Validate() const;
  bool operator==(const ViewSamplingOptions&) const = default;
};

// SampleViews refuses grids larger than this (a typo such as a 0.001 degree step would otherwise
// ask for billions of views before anything could say it is too much).
inline constexpr std::size_t kMaxSampledViews = 10'000'000;

// The number of views SampleViews returns, computed without sampling them (validates first).
std::size_t CountViews(const ViewSamplingOptions& options);

// Throws Error when the options are invalid or give more than kMaxSampledViews views.
std::vector<ViewAngles> SampleViews(const ViewSamplingOptions& options);

// Camera pose that sees the sphere centre `centre_in_model` at distance `distance_mm` on the
// optical axis, from `view` (angles in the upright frame of `upright_from_model`). Image "up"
// follows the upright +Z, then `roll_deg` is applied. Returns the true cam_from_model.
Pose CamFromModelForView(const ViewAngles& view, const Eigen::Vector3d& centre_in_model,
                         double distance_mm,
                         const Eigen::Matrix3d& upright_from_model = Eigen::Matrix3d::Identity());

// Depth layers covering [min_mm, max_mm] with a step of at most `step_mm` (the sphere radius, paper
// §3.1), so that no depth of the range is farther than step_mm / 2 from a layer. Throws Error on
// an empty or invalid range.
std::vector<double> DepthLayers(double min_mm, double max_mm, double step_mm);

}  // namespace layermod
