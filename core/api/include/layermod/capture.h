// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <opencv2/core/mat.hpp>

#include <layermod/camera.h>

namespace layermod::api {

// One RGB-D (or RGB) frame. The images are referenced, not copied (cv::Mat headers).
struct Capture {
  cv::Mat color_bgr;  // CV_8UC3, BGR, camera.width x camera.height
  // CV_16UC1 (value x depth_scale = mm) or CV_32FC1 in mm; 0 = no measurement. Same size as the
  // colour. Empty for RGB-only frames (the "color-only" detector mode).
  cv::Mat depth;
  double depth_scale = 1.0;  // for 16-bit depth only
  Camera camera;
};

// Reads a frame from files: an 8-bit colour (or grey) PNG/JPEG, a 16-bit depth PNG (value x
// depth_scale = mm; empty path: no depth) and a BOP camera.json. Throws IoError / FormatError
// naming the file: unreadable images, colour/depth of different sizes, images of another size
// than the camera, 8-bit depth, depth without a single valid pixel.
Capture LoadCapture(const std::filesystem::path& color, const std::filesystem::path& depth,
                    const std::filesystem::path& camera_json, double depth_scale = 1.0);

}  // namespace layermod::api
