// SPDX-License-Identifier: MIT
#include "ui/detection_overlays.h"

#include "pipeline/overlays.h"

namespace layermod::ui {
namespace {

// Copies into `canvas` the pixels where `drawn` differs from `base`.
void KeepDrawnPixels(const cv::Mat& drawn, const cv::Mat& base, cv::Mat& canvas) {
  cv::Mat difference;
  cv::absdiff(drawn, base, difference);
  cv::Mat changed;
  cv::transform(difference, changed, cv::Matx13f(1.0f, 1.0f, 1.0f));
  drawn.copyTo(canvas, changed > 0.0f);
}

}  // namespace

cv::Mat ComposeDetectionOverlays(const Capture& capture, const DetectionResult& result,
                                 const Detector& detector, const OverlayToggles& toggles) {
  const cv::Mat& color = capture.color;
  if (color.empty() || detector.archives().empty()) return color.clone();
  // The stage pictures dim the image the same way; an empty match list gives just that.
  const cv::Mat dimmed = DrawMatches(color, ObjectDiagnostics{}, detector.archives().front());
  cv::Mat canvas = toggles.any_stage() ? dimmed.clone() : color.clone();
  for (const ObjectDiagnostics& diagnostics : result.diagnostics) {
    const bool has_division = !diagnostics.division.blocks.empty();
    if (toggles.regions && has_division) {
      KeepDrawnPixels(DrawRegionDivision(color, diagnostics, detector.Object(diagnostics.obj_id)),
                      dimmed, canvas);
    }
    if (toggles.coarse && has_division && !diagnostics.coarse.evaluated.empty()) {
      KeepDrawnPixels(DrawCoarsePositioning(color, diagnostics), dimmed, canvas);
    }
    if (toggles.matches) {
      KeepDrawnPixels(DrawMatches(color, diagnostics, detector.ArchiveOf(diagnostics.obj_id)),
                      dimmed, canvas);
    }
  }
  if (toggles.poses) {
    KeepDrawnPixels(DrawPoses(color, result.detections, detector, capture.camera), color, canvas);
  }
  return canvas;
}

}  // namespace layermod::ui
