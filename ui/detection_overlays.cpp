// SPDX-License-Identifier: MIT
#include "ui/detection_overlays.h"

#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <vector>

#include "pipeline/overlays.h"

namespace layermod::ui {
namespace {

// Match labels ("#123 87.5%") closer than this to a better match's label would overlap it.
constexpr int kLabelGapXPx = 90;
constexpr int kLabelGapYPx = 16;
constexpr std::size_t kMaxMatchLabels = 6;
constexpr int kPoseLabelWidthPx = 260;
// DrawRegionDivision's legend: one 18 px line per layer from y = 6.
constexpr int kLayerLegendLinePx = 18;
constexpr int kLayerLegendTopPx = 6;

// Where `drawn` differs from `base` (CV_8U, 255 = changed).
cv::Mat DrawnMask(const cv::Mat& drawn, const cv::Mat& base) {
  cv::Mat difference;
  cv::absdiff(drawn, base, difference);
  cv::Mat changed;
  cv::transform(difference, changed, cv::Matx13f(1.0f, 1.0f, 1.0f));
  return changed > 0.0f;
}

// Copies into `canvas` the pixels where `drawn` differs from `base`.
void KeepDrawnPixels(const cv::Mat& drawn, const cv::Mat& base, cv::Mat& canvas) {
  drawn.copyTo(canvas, DrawnMask(drawn, base));
}

// Where DrawPoses writes each detection's label ("bracket 96.0% conf 0.98", right of and above
// the projected sphere centre), with room for a long object name.
std::vector<cv::Rect> PoseLabelBoxes(const DetectionResult& result, const Detector& detector,
                                     const PinholeCamera& camera) {
  std::vector<cv::Rect> boxes;
  for (const Detection& detection : result.detections) {
    const Eigen::Vector2d centre =
        camera.Project(detection.cam_from_model * detector.Object(detection.obj_id).sphere.centre);
    boxes.emplace_back(static_cast<int>(centre.x()) + 8, static_cast<int>(centre.y()) - 24,
                       kPoseLabelWidthPx, 20);
  }
  return boxes;
}

// The best matches whose labels overlap neither a better one's nor a pose label (`reserved`), at
// most kMaxMatchLabels: the detector keeps several matches per location (NMS), and their labels
// would pile up.
ObjectDiagnostics MatchesWithSeparateLabels(const ObjectDiagnostics& diagnostics,
                                            const std::vector<cv::Rect>& reserved) {
  ObjectDiagnostics kept;
  kept.obj_id = diagnostics.obj_id;
  for (const RawMatch& match : diagnostics.matches) {
    bool overlaps = false;
    for (const RawMatch& other : kept.matches) {
      overlaps = overlaps || (std::abs(match.x - other.x) < kLabelGapXPx &&
                              std::abs(match.y - other.y) < kLabelGapYPx);
    }
    const cv::Rect label(match.x, match.y - kLabelGapYPx - 4, kLabelGapXPx, kLabelGapYPx);
    for (const cv::Rect& box : reserved) overlaps = overlaps || (label & box).area() > 0;
    if (!overlaps) kept.matches.push_back(match);
    if (kept.matches.size() == kMaxMatchLabels) break;
  }
  return kept;
}

// The coarse-positioning picture; its legend moved down by `legend_shift_px` so that it sits
// below the region division's legend when both are shown.
void KeepCoarsePixels(const cv::Mat& color, const ObjectDiagnostics& diagnostics,
                      const cv::Mat& dimmed, int legend_shift_px, cv::Mat& canvas) {
  const cv::Mat full = DrawCoarsePositioning(color, diagnostics);
  // With nothing evaluated the picture is its legend alone.
  const cv::Mat legend = DrawCoarsePositioning(color, ObjectDiagnostics{});
  const cv::Mat legend_mask = DrawnMask(legend, dimmed);
  full.copyTo(canvas, DrawnMask(full, dimmed) & ~legend_mask);
  const cv::Matx23d shift(1, 0, 0, 0, 1, legend_shift_px);
  cv::Mat moved_legend;
  cv::Mat moved_mask;
  cv::warpAffine(legend, moved_legend, shift, legend.size(), cv::INTER_NEAREST);
  cv::warpAffine(legend_mask, moved_mask, shift, legend.size(), cv::INTER_NEAREST);
  moved_legend.copyTo(canvas, moved_mask);
}

}  // namespace

cv::Mat ComposeDetectionOverlays(const Capture& capture, const DetectionResult& result,
                                 const Detector& detector, const OverlayToggles& toggles) {
  const cv::Mat& color = capture.color;
  if (color.empty() || detector.archives().empty()) return color.clone();
  // The stage pictures dim the image the same way; an empty match list gives just that.
  const cv::Mat dimmed = DrawMatches(color, ObjectDiagnostics{}, *detector.archives().front());
  cv::Mat canvas = toggles.any_stage() ? dimmed.clone() : color.clone();
  const std::vector<cv::Rect> pose_labels =
      toggles.poses ? PoseLabelBoxes(result, detector, capture.camera) : std::vector<cv::Rect>{};
  for (const ObjectDiagnostics& diagnostics : result.diagnostics) {
    const bool has_division = !diagnostics.division.blocks.empty();
    const ArchiveObject& object = detector.Object(diagnostics.obj_id);
    const bool draw_regions = toggles.regions && has_division;
    if (draw_regions) {
      KeepDrawnPixels(DrawRegionDivision(color, diagnostics, object), dimmed, canvas);
    }
    if (toggles.coarse && has_division && !diagnostics.coarse.evaluated.empty()) {
      const int layers = static_cast<int>(object.layer_depths_mm.size());
      const int shift_px = draw_regions ? kLayerLegendTopPx + kLayerLegendLinePx * layers : 0;
      KeepCoarsePixels(color, diagnostics, dimmed, shift_px, canvas);
    }
    if (toggles.matches) {
      KeepDrawnPixels(DrawMatches(color, MatchesWithSeparateLabels(diagnostics, pose_labels),
                                  detector.ArchiveOf(diagnostics.obj_id)),
                      dimmed, canvas);
    }
  }
  if (toggles.poses) {
    KeepDrawnPixels(DrawPoses(color, result.detections, detector, capture.camera), color, canvas);
  }
  return canvas;
}

}  // namespace layermod::ui
