// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <layermod/archive.h>
#include <layermod/camera.h>
#include <layermod/capture.h>
#include <layermod/detection.h>

namespace layermod::api {

// Detects the objects of one or more archives in captures taken with the archives' camera.
//
// Options are a JSON object with the names of `layermod detect`'s flags ('-' as '_'), e.g.
// {"mode": "scene-patch", "threshold": 70, "instances": 1}; absent fields keep their defaults
// (docs: README "detect"). A JSON string keeps this header free of the core's option structs,
// which change between versions while the names do not.
//
// Thread-safety: Detect is const and only reads the detector (the archives and the per-object
// data prepared at construction); per-call scratch is local or per thread. One Detector may
// serve several threads at once; each Detect call also runs in parallel inside (TBB).
class Detector {
 public:
  // Shares the archives (no copy). Throws layermod::Error when there is no archive, archives
  // disagree on the camera or the feature parameters, an object id appears twice; FormatError
  // for bad options (unknown name, wrong type, out of range), naming the field.
  explicit Detector(std::vector<Archive> archives, std::string_view options_json = "{}");

  // The same archives and prepared data with other options (cheap: nothing is rebuilt).
  Detector WithOptions(std::string_view options_json) const;

  // Detects in one frame. Nothing found is an empty result, not an error. Throws
  // layermod::Error for an unusable capture: colour not CV_8UC3, depth neither CV_16UC1 nor
  // CV_32FC1, colour and depth of different sizes, images of another size than the camera,
  // intrinsics other than the archives', no depth in a mode that needs it. Float depth that is
  // NaN, infinite or negative counts as no measurement.
  DetectionResult Detect(const Capture& capture) const;

  Camera camera() const;            // the archives' camera
  std::string OptionsJson() const;  // every option in effect, as JSON
  const std::vector<Archive>& archives() const;

 private:
  struct Shared;
  struct Settings;
  Detector(std::shared_ptr<const Shared> shared, std::shared_ptr<const Settings> settings);
  std::shared_ptr<const Shared> shared_;
  std::shared_ptr<const Settings> settings_;
};

}  // namespace layermod::api
