// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>

namespace layermod {

// Pinhole camera in pixels; the same model renders templates and describes the sensor.
// Pixel centres are at integer coordinates: a point projects to (fx*x/z + cx, fy*y/z + cy).
struct PinholeCamera {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  int width = 0;
  int height = 0;

  // Throws Error when a value is missing, non-finite or out of range.
  void Validate() const;

  Eigen::Vector2d Project(const Eigen::Vector3d& point_in_cam) const {
    return {fx * point_in_cam.x() / point_in_cam.z() + cx,
            fy * point_in_cam.y() / point_in_cam.z() + cy};
  }
  Eigen::Vector3d Backproject(const Eigen::Vector2d& pixel, double depth_mm) const {
    return {(pixel.x() - cx) * depth_mm / fx, (pixel.y() - cy) * depth_mm / fy, depth_mm};
  }
  // Scales the intrinsics and image size by `factor` (e.g. 0.5 for a pyramid level).
  PinholeCamera Scaled(double factor) const;
  // The camera that sees every `step`-th pixel of this one: its pixel (x, y) is this camera's
  // pixel (step*x, step*y), exactly, because pixel centres sit at integer coordinates. Throws
  // Error when step < 1.
  PinholeCamera EveryNthPixel(int step) const;

  bool operator==(const PinholeCamera&) const = default;
};

// Reads a BOP camera file (`fx fy cx cy width height`, `depth_scale` optional). Throws IoError or
// FormatError naming the file and the missing or invalid field.
PinholeCamera LoadCameraJson(const std::filesystem::path& path);

// The intrinsics and image size as a JSON object (`fx fy cx cy width height`): what
// LoadCameraJson reads, and the camera of the archive manifest, `inspect --json` and BOP's
// camera.json (which adds `depth_scale`).
nlohmann::json CameraJson(const PinholeCamera& camera);

}  // namespace layermod
