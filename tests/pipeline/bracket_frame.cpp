// SPDX-License-Identifier: MIT
#include "bracket_frame.h"

#include "eval_fixtures.h"

namespace layermod::test {
namespace {

DetectedBracketFrame MakeBracketFrame() {
  TemplateArchive archive = TrainBracketArchive(650.0, 750.0);
  const TemplateRecord record = archive.templates()[archive.templates().size() / 2];
  const Capture capture = CaptureAtTemplatePose(archive, record);
  Detector detector({std::move(archive)});
  DetectorOptions options;
  options.min_confidence = 0.0;
  DetectionResult result = detector.Detect(capture, options);
  return {std::move(detector), capture, record.cam_from_model, std::move(result)};
}

}  // namespace

const DetectedBracketFrame& BracketFrame() {
  static const DetectedBracketFrame frame = MakeBracketFrame();
  return frame;
}

}  // namespace layermod::test
