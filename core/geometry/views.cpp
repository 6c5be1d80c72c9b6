// SPDX-License-Identifier: MIT
#include "geometry/views.h"

#include <Eigen/Geometry>
#include <charconv>
#include <cmath>
#include <sstream>

#include "geometry/up_axis.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kAngleEps = 1e-9;

double ParseDouble(std::string_view text, std::string_view name) {
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    throw Error(std::string(name) + ": '" + std::string(text) + "' is not a number");
  }
  return value;
}

// Fibonacci lattice on the whole sphere with about `spacing_deg` between neighbours; keeps the
// directions whose elevation lies in `elevation`.
int FibonacciPointCount(double spacing_deg) {
  const double spacing_rad = DegToRad(spacing_deg);
  return std::max(2, static_cast<int>(std::lround(4.0 * kPi / (spacing_rad * spacing_rad))));
}

double FibonacciElevationDeg(int i, int count) {
  return RadToDeg(std::asin(1.0 - (2.0 * i + 1.0) / count));
}

bool InElevationRange(double elevation_deg, const AngleRange& elevation) {
  return elevation_deg >= elevation.min_deg - kAngleEps &&
         elevation_deg <= elevation.max_deg + kAngleEps;
}

std::vector<ViewAngles> EvenDirections(double spacing_deg, const AngleRange& elevation) {
  const int count = FibonacciPointCount(spacing_deg);
  const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
  std::vector<ViewAngles> views;
  for (int i = 0; i < count; ++i) {
    const double elevation_deg = FibonacciElevationDeg(i, count);
    if (!InElevationRange(elevation_deg, elevation)) continue;
    double azimuth_deg = std::fmod(RadToDeg(golden_angle * i), 360.0);
    views.push_back({azimuth_deg, elevation_deg, 0.0});
  }
  return views;
}

std::size_t CountEvenDirections(double spacing_deg, const AngleRange& elevation) {
  const int count = FibonacciPointCount(spacing_deg);
  std::size_t kept = 0;
  for (int i = 0; i < count; ++i)
    kept += InElevationRange(FibonacciElevationDeg(i, count), elevation);
  return kept;
}

}  // namespace

Eigen::Vector3d DirectionFromAngles(double azimuth_deg, double elevation_deg) {
  const double az = DegToRad(azimuth_deg);
  const double el = DegToRad(elevation_deg);
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

void AngleRange::Validate(std::string_view name) const {
  if (!std::isfinite(min_deg) || !std::isfinite(step_deg) || !std::isfinite(max_deg)) {
    throw Error(std::string(name) + " range: values must be finite");
  }
  if (step_deg <= 0.0) throw Error(std::string(name) + " range: step must be positive");
  if (max_deg < min_deg) throw Error(std::string(name) + " range: max is below min, no view");
  if ((max_deg - min_deg) / step_deg > 100000.0) {
    throw Error(std::string(name) + " range: step too small (more than 100000 values)");
  }
}

std::size_t AngleRange::Count() const {
  return static_cast<std::size_t>(std::floor((max_deg - min_deg) / step_deg + 1e-6)) + 1;
}

std::vector<double> AngleRange::Values() const {
  std::vector<double> values;
  const std::size_t count = Count();
  values.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    values.push_back(min_deg + static_cast<double>(i) * step_deg);
  return values;
}

std::string AngleRange::ToString() const {
  std::ostringstream out;
  out << min_deg << ':' << step_deg << ':' << max_deg;
  return out.str();
}

AngleRange AngleRange::Parse(std::string_view text, std::string_view name) {
  const auto first = text.find(':');
  const auto second = first == std::string_view::npos ? first : text.find(':', first + 1);
  if (second == std::string_view::npos || text.find(':', second + 1) != std::string_view::npos) {
    throw Error(std::string(name) + ": expected min:step:max, got '" + std::string(text) + "'");
  }
  AngleRange range{ParseDouble(text.substr(0, first), name),
                   ParseDouble(text.substr(first + 1, second - first - 1), name),
                   ParseDouble(text.substr(second + 1), name)};
  range.Validate(name);
  return range;
}

void ViewSamplingOptions::Validate() const {
  azimuth.Validate("azimuth");
  elevation.Validate("elevation");
  roll.Validate("roll");
  if (elevation.min_deg < -90.0 || elevation.max_deg > 90.0) {
    throw Error("elevation range: values must lie within -90..90 degrees");
  }
  if (!std::isfinite(even_spacing_deg) || even_spacing_deg < 0.0 ||
      (even_spacing_deg > 0.0 && even_spacing_deg < 0.5)) {
    throw Error("even view spacing: must be 0 (grid) or at least 0.5 degrees");
  }
  ValidateRotation(upright_from_model, "up rotation (upright_from_model)");
}

std::size_t CountViews(const ViewSamplingOptions& options) {
  options.Validate();
  const std::size_t directions =
      options.even_spacing_deg > 0.0
          ? CountEvenDirections(options.even_spacing_deg, options.elevation)
          : options.elevation.Count() * options.azimuth.Count();
  return directions * options.roll.Count();  // each count <= 100001: no overflow
}

std::vector<ViewAngles> SampleViews(const ViewSamplingOptions& options) {
  const std::size_t count = CountViews(options);
  if (count > kMaxSampledViews) {
    throw Error("views: the view ranges give " + std::to_string(count) + " views, more than " +
                std::to_string(kMaxSampledViews) + "; use larger angle steps");
  }
  std::vector<ViewAngles> directions;
  if (options.even_spacing_deg > 0.0) {
    directions = EvenDirections(options.even_spacing_deg, options.elevation);
  } else {
    for (double elevation_deg : options.elevation.Values()) {
      for (double azimuth_deg : options.azimuth.Values()) {
        directions.push_back({azimuth_deg, elevation_deg, 0.0});
      }
    }
  }
  std::vector<ViewAngles> views;
  views.reserve(directions.size() * options.roll.Values().size());
  for (const ViewAngles& direction : directions) {
    for (double roll_deg : options.roll.Values()) {
      views.push_back({direction.azimuth_deg, direction.elevation_deg, roll_deg});
    }
  }
  return views;
}

namespace {

// The view's camera pose in the upright frame.
Pose CamFromUprightForView(const ViewAngles& view, const Eigen::Vector3d& centre_in_upright,
                           double distance_mm) {
  const Eigen::Vector3d to_camera = DirectionFromAngles(view.azimuth_deg, view.elevation_deg);
  const Eigen::Vector3d forward = -to_camera;  // camera +Z, towards the object
  // Camera +Y points down in the image: align it with the upright -Z, projected on the image
  // plane. At the poles that is undefined; use the azimuth direction instead.
  Eigen::Vector3d down = -Eigen::Vector3d::UnitZ();
  down -= down.dot(forward) * forward;
  if (down.norm() < 1e-6) {
    const double az = DegToRad(view.azimuth_deg);
    down = Eigen::Vector3d(std::cos(az), std::sin(az), 0.0) * (view.elevation_deg > 0 ? 1.0 : -1.0);
  }
  down.normalize();
  const Eigen::Vector3d right = down.cross(forward);
  Eigen::Matrix3d cam_from_upright_rotation;
  cam_from_upright_rotation.row(0) = right.transpose();
  cam_from_upright_rotation.row(1) = down.transpose();
  cam_from_upright_rotation.row(2) = forward.transpose();
  const Eigen::Matrix3d roll =
      Eigen::AngleAxisd(DegToRad(view.roll_deg), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Pose pose;
  pose.R = roll * cam_from_upright_rotation;
  const Eigen::Vector3d camera_position = centre_in_upright + distance_mm * to_camera;
  pose.t = -(pose.R * camera_position);
  return pose;
}

}  // namespace

Pose CamFromModelForView(const ViewAngles& view, const Eigen::Vector3d& centre_in_model,
                         double distance_mm, const Eigen::Matrix3d& upright_from_model) {
  const Pose cam_from_upright =
      CamFromUprightForView(view, upright_from_model * centre_in_model, distance_mm);
  return {cam_from_upright.R * upright_from_model, cam_from_upright.t};
}

std::vector<double> DepthLayers(double min_mm, double max_mm, double step_mm) {
  if (!std::isfinite(min_mm) || !std::isfinite(max_mm) || !std::isfinite(step_mm)) {
    throw Error("depth range: values must be finite");
  }
  if (min_mm <= 0.0) throw Error("depth range: D_min must be positive");
  if (min_mm >= max_mm) throw Error("depth range: D_min must be below D_max");
  if (step_mm <= 0.0) throw Error("depth range: layer step (sphere radius) must be positive");
  const int count = std::max(1, static_cast<int>(std::ceil((max_mm - min_mm) / step_mm - 1e-9)));
  if (count > 10000) throw Error("depth range: more than 10000 depth layers");
  const double spacing = (max_mm - min_mm) / count;
  std::vector<double> layers;
  for (int i = 0; i < count; ++i) layers.push_back(min_mm + spacing * (i + 0.5));
  return layers;
}

}  // namespace layermod
