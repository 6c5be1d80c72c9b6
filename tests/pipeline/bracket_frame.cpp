// SPDX-License-Identifier: MIT
#include "bracket_frame.h"

#include "eval_fixtures.h"
#include "render/rasterizer.h"

namespace layermod::test {
namespace {

constexpr float kBackgroundBehindMm = 150.0f;  // a wall this far behind the part

// The bracket rendered at the pose of one of its templates, in front of a grey wall: the
// template matches it exactly, so the detector must find it.
Capture CaptureAtTemplatePose(const TemplateArchive& archive, const TemplateRecord& record) {
  const PinholeCamera& camera = archive.camera();
  const RenderedView view =
      RenderView(archive.Object(record.obj_id).mesh, camera, record.cam_from_model);
  Capture capture;
  capture.camera = camera;
  capture.color = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar(70, 80, 90));
  capture.depth_mm = cv::Mat(camera.height, camera.width, CV_32F,
                             cv::Scalar(record.layer_depth_mm + kBackgroundBehindMm));
  view.color.copyTo(capture.color(view.roi), view.mask);
  view.depth_mm.copyTo(capture.depth_mm(view.roi), view.mask);
  return capture;
}

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
