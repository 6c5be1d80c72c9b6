// SPDX-License-Identifier: MIT
#include <layermod/capture.h>

#include "api/archive_access.h"
#include "pipeline/capture_io.h"

namespace layermod::api {

Capture LoadCapture(const std::filesystem::path& color, const std::filesystem::path& depth,
                    const std::filesystem::path& camera_json, double depth_scale) {
  CaptureFiles files;
  files.color = color;
  files.depth = depth;
  files.camera = camera_json;
  files.depth_scale = depth_scale;
  const layermod::Capture loaded = layermod::LoadCapture(files);
  Capture capture;
  capture.color_bgr = loaded.color;
  capture.depth = loaded.depth_mm;  // CV_32F mm after loading, so the scale is applied
  capture.camera = FromCore(loaded.camera);
  return capture;
}

}  // namespace layermod::api
