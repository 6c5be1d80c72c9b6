// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

namespace layermod::api {

// Pinhole intrinsics in pixels, pixel centres at integer coordinates: a point (x, y, z) of the
// camera frame (mm, z forward) projects to (fx x / z + cx, fy y / z + cy). Templates are
// rendered with the archive's camera, so captures must come with the same intrinsics.
struct Camera {
  double fx = 0.0;
  double fy = 0.0;
  double cx = 0.0;
  double cy = 0.0;
  int width = 0;
  int height = 0;

  // Throws layermod::Error when a value is non-finite or out of range.
  void Validate() const;

  // Reads a BOP camera.json (`fx fy cx cy width height`). Throws IoError / FormatError naming
  // the file and the missing or invalid field.
  static Camera FromJson(const std::filesystem::path& path);

  bool operator==(const Camera&) const = default;
};

}  // namespace layermod::api
