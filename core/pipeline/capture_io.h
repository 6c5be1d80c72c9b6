// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

#include "pipeline/detector.h"

namespace layermod {

enum class DepthUnit { kMillimetre, kMetre };

struct CaptureFiles {
  std::filesystem::path color;   // 8-bit colour (or grey) PNG/JPEG
  std::filesystem::path depth;   // 16-bit PNG in mm (scaled by depth_scale), or a 32-bit float
                                 // image (TIFF/EXR) in float_depth_unit (mm or m); may be empty
  std::filesystem::path camera;  // BOP camera.json
  double depth_scale = 1.0;      // 16-bit value * depth_scale = mm
  DepthUnit float_depth_unit = DepthUnit::kMillimetre;  // unit of float depth images
};

// Loads and validates a capture. Throws IoError/FormatError naming the file: unreadable images,
// colour/depth size mismatch, size different from the camera file, 8-bit depth (a common export
// mistake), all-invalid depth. NaN/inf/negative depth becomes 0 (invalid).
Capture LoadCapture(const CaptureFiles& files);

}  // namespace layermod
