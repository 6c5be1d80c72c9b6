// SPDX-License-Identifier: MIT
#include <layermod/detector.h>

#include <opencv2/core.hpp>

#include "api/archive_access.h"
#include "api/detection_convert.h"
#include "pipeline/detector.h"
#include "pipeline/detector_options.h"
#include "scene/depth_mm.h"
#include "util/error.h"

namespace layermod::api {

struct Detector::Shared {
  std::vector<Archive> archives;
  layermod::Detector detector;
};

struct Detector::Settings {
  DetectorOptions options;
};

namespace {

DetectorOptions ParseOptions(std::string_view options_json) {
  const nlohmann::json json = nlohmann::json::parse(options_json, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    throw FormatError("detector options: not a JSON object");
  }
  DetectorOptions options = DetectorOptionsFromJson(json, "detector options");
  options.Validate();
  return options;
}

std::vector<std::shared_ptr<const TemplateArchive>> CoreArchives(
    const std::vector<Archive>& archives) {
  std::vector<std::shared_ptr<const TemplateArchive>> core;
  core.reserve(archives.size());
  for (const Archive& archive : archives) core.push_back(ArchiveAccess::Core(archive));
  return core;
}

std::string TypeName(const cv::Mat& image) {
  return cv::typeToString(image.type()) + " " + std::to_string(image.cols) + "x" +
         std::to_string(image.rows);
}

// The core detector takes CV_32F depth in mm with 0 = no measurement.
cv::Mat DepthMm(const Capture& capture) {
  if (capture.depth.empty()) return {};
  try {
    return DepthToMillimetres(capture.depth, DepthScale{capture.depth_scale, 1.0});
  } catch (const Error& error) {
    throw Error("capture: " + std::string(error.what()) + " (depth " + TypeName(capture.depth) +
                "; expected CV_16UC1 scaled to mm by depth_scale, or CV_32FC1 mm)");
  }
}

}  // namespace

Detector::Detector(std::vector<Archive> archives, std::string_view options_json)
    : settings_(std::make_shared<const Settings>(Settings{ParseOptions(options_json)})) {
  const auto core = CoreArchives(archives);
  shared_ = std::make_shared<const Shared>(Shared{std::move(archives), layermod::Detector(core)});
}

Detector::Detector(std::shared_ptr<const Shared> shared, std::shared_ptr<const Settings> settings)
    : shared_(std::move(shared)), settings_(std::move(settings)) {}

Detector Detector::WithOptions(std::string_view options_json) const {
  return Detector(shared_, std::make_shared<const Settings>(Settings{ParseOptions(options_json)}));
}

DetectionResult Detector::Detect(const Capture& capture) const {
  if (!capture.color_bgr.empty() && capture.color_bgr.type() != CV_8UC3) {
    throw Error("capture: colour must be CV_8UC3 (8-bit BGR), got " + TypeName(capture.color_bgr));
  }
  const layermod::Capture core{capture.color_bgr, DepthMm(capture), ToCore(capture.camera)};
  const layermod::DetectionResult result = shared_->detector.Detect(core, settings_->options);
  return FromCore(result, settings_->options.mode);
}

Camera Detector::camera() const { return FromCore(shared_->detector.camera()); }

std::string Detector::OptionsJson() const {
  return DetectorOptionsToJson(settings_->options).dump();
}

const std::vector<Archive>& Detector::archives() const { return shared_->archives; }

}  // namespace layermod::api
