// SPDX-License-Identifier: MIT
#include "geometry/camera.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

double ReadNumber(const nlohmann::json& json, const char* key, const std::filesystem::path& path) {
  if (!json.contains(key)) {
    throw FormatError(Quoted(path) + ": camera field " + Quoted(std::string_view(key)) +
                      " is missing");
  }
  if (!json[key].is_number()) {
    throw FormatError(Quoted(path) + ": camera field " + Quoted(std::string_view(key)) +
                      " is not a number");
  }
  return json[key].get<double>();
}

}  // namespace

void PinholeCamera::Validate() const {
  const bool finite =
      std::isfinite(fx) && std::isfinite(fy) && std::isfinite(cx) && std::isfinite(cy);
  if (!finite) throw Error("camera: intrinsics must be finite numbers");
  if (fx <= 0.0 || fy <= 0.0) throw Error("camera: focal lengths fx, fy must be positive");
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    throw Error("camera: image size must be between 1 and 16384 pixels");
  }
}

PinholeCamera PinholeCamera::Scaled(double factor) const {
  PinholeCamera scaled = *this;
  scaled.fx *= factor;
  scaled.fy *= factor;
  // Keep pixel centres consistent: the continuous image coordinate (u + 0.5) scales.
  scaled.cx = (cx + 0.5) * factor - 0.5;
  scaled.cy = (cy + 0.5) * factor - 0.5;
  scaled.width = static_cast<int>(std::lround(width * factor));
  scaled.height = static_cast<int>(std::lround(height * factor));
  return scaled;
}

PinholeCamera PinholeCamera::EveryNthPixel(int step) const {
  if (step < 1) throw Error("camera: the pixel step must be at least 1");
  PinholeCamera sampled = *this;
  sampled.fx /= step;
  sampled.fy /= step;
  sampled.cx /= step;
  sampled.cy /= step;
  sampled.width = (width + step - 1) / step;
  sampled.height = (height + step - 1) / step;
  return sampled;
}

PinholeCamera LoadCameraJson(const std::filesystem::path& path) {
  const std::string text = ReadFileBytes(path);
  nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object()) {
    throw FormatError(Quoted(path) + ": not a JSON object");
  }
  PinholeCamera camera;
  camera.fx = ReadNumber(json, "fx", path);
  camera.fy = ReadNumber(json, "fy", path);
  camera.cx = ReadNumber(json, "cx", path);
  camera.cy = ReadNumber(json, "cy", path);
  const double width = ReadNumber(json, "width", path);
  const double height = ReadNumber(json, "height", path);
  if (width != std::floor(width) || height != std::floor(height) || width < 1 || height < 1 ||
      width > 16384 || height > 16384) {
    throw FormatError(Quoted(path) + ": width and height must be positive integers");
  }
  camera.width = static_cast<int>(width);
  camera.height = static_cast<int>(height);
  try {
    camera.Validate();
  } catch (const Error& error) {
    throw FormatError(Quoted(path) + ": " + error.what());
  }
  return camera;
}

nlohmann::json CameraJson(const PinholeCamera& camera) {
  return {{"fx", camera.fx}, {"fy", camera.fy},       {"cx", camera.cx},
          {"cy", camera.cy}, {"width", camera.width}, {"height", camera.height}};
}

}  // namespace layermod
