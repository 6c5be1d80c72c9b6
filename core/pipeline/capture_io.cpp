// SPDX-License-Identifier: MIT
#include "pipeline/capture_io.h"
#include "util/quoted.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

#include "dataset/image_header.h"
#include "scene/depth_mm.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

// The header is checked against the camera before decoding: a header can declare any size.
cv::Mat ReadImage(const std::filesystem::path& path, int flags, const CaptureFiles& files,
                  const PinholeCamera& camera) {
  if (!std::filesystem::is_regular_file(path)) throw IoError(Quoted(path) + ": no such file");
  const std::string bytes = ReadFileBytes(path);
  CheckDeclaredImageSize(path, bytes, cv::Size(camera.width, camera.height), Quoted(files.camera));
  cv::Mat image = DecodeImageBytes(bytes, flags);
  if (image.empty()) throw FormatError(Quoted(path) + ": not a readable image");
  return image;
}

cv::Mat LoadColor(const CaptureFiles& files, const PinholeCamera& camera) {
  const std::filesystem::path& path = files.color;
  cv::Mat image = ReadImage(path, cv::IMREAD_UNCHANGED, files, camera);
  if (image.depth() != CV_8U) {
    throw FormatError(Quoted(path) + ": colour image must have 8 bits per channel");
  }
  if (image.channels() == 1) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  if (image.channels() != 3) throw FormatError(Quoted(path) + ": unsupported channel count");
  return image;
}

cv::Mat LoadDepth(const CaptureFiles& files, const PinholeCamera& camera) {
  const cv::Mat raw =
      ReadImage(files.depth, cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR, files, camera);
  const DepthScale scale{files.depth_scale,
                         files.float_depth_unit == DepthUnit::kMetre ? 1000.0 : 1.0};
  cv::Mat depth_mm;
  try {
    depth_mm = DepthToMillimetres(raw, scale);
  } catch (const Error& error) {
    throw FormatError(Quoted(files.depth) + ": " + error.what());
  }
  if (cv::countNonZero(depth_mm) == 0) {
    throw FormatError(Quoted(files.depth) + ": no valid depth (all pixels are 0 or invalid)");
  }
  return depth_mm;
}

}  // namespace

Capture LoadCapture(const CaptureFiles& files) {
  if (!(files.depth_scale > 0.0) || !std::isfinite(files.depth_scale)) {
    throw Error("depth scale must be a positive number");
  }
  Capture capture;
  capture.camera = LoadCameraJson(files.camera);
  capture.color = LoadColor(files, capture.camera);
  if (capture.color.cols != capture.camera.width || capture.color.rows != capture.camera.height) {
    throw FormatError(Quoted(files.color) + ": image is " + std::to_string(capture.color.cols) +
                      "x" + std::to_string(capture.color.rows) + " but " + Quoted(files.camera) +
                      " says " + std::to_string(capture.camera.width) + "x" +
                      std::to_string(capture.camera.height));
  }
  if (!files.depth.empty()) {
    capture.depth_mm = LoadDepth(files, capture.camera);
    if (capture.depth_mm.size() != capture.color.size()) {
      throw FormatError(
          Quoted(files.depth) + ": depth is " + std::to_string(capture.depth_mm.cols) + "x" +
          std::to_string(capture.depth_mm.rows) + ", colour is " +
          std::to_string(capture.color.cols) + "x" + std::to_string(capture.color.rows));
    }
  }
  return capture;
}

}  // namespace layermod
