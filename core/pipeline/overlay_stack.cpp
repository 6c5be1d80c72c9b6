// SPDX-License-Identifier: MIT
#include "pipeline/overlay_stack.h"

#include <cstdlib>
#include <vector>

#include "pipeline/overlays.h"

namespace layermod {
namespace {

// Match labels ("#123 87.5%") closer than this to a better match's label would overlap it.
constexpr int kLabelGapXPx = 90;
constexpr int kLabelGapYPx = 16;
constexpr std::size_t kMaxMatchLabels = 6;
constexpr int kPoseLabelWidthPx = 260;

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

// One object's stage pictures before the poses, the legends from the top-left corner down.
void DrawObjectStages(cv::Mat& canvas, const ObjectDiagnostics& diagnostics,
                      const Detector& detector, const OverlayToggles& toggles,
                      const std::vector<cv::Rect>& pose_labels) {
  const bool has_division = !diagnostics.division.blocks.empty();
  const ArchiveObject& object = detector.Object(diagnostics.obj_id);
  int legend_px = 0;
  if (toggles.regions && has_division) {
    DrawRegionDivision(canvas, diagnostics, object);
    legend_px = DrawLayerLegend(canvas, object, legend_px);
  }
  if (toggles.coarse && has_division && !diagnostics.coarse.evaluated.empty()) {
    DrawCoarsePositioning(canvas, diagnostics);
    DrawCoarseLegend(canvas, legend_px);
  }
  if (toggles.matches) {
    DrawMatches(canvas, MatchesWithSeparateLabels(diagnostics, pose_labels),
                detector.ArchiveOf(diagnostics.obj_id));
  }
}

}  // namespace

cv::Mat ComposeStageOverlays(const Capture& capture, const DetectionResult& result,
                             const Detector& detector, const OverlayToggles& toggles) {
  cv::Mat canvas = capture.color.clone();
  if (canvas.empty() || detector.archives().empty()) return canvas;
  if (toggles.any_stage()) DimColor(canvas);
  const std::vector<cv::Rect> pose_labels =
      toggles.poses ? PoseLabelBoxes(result, detector, capture.camera) : std::vector<cv::Rect>{};
  for (const ObjectDiagnostics& diagnostics : result.diagnostics) {
    DrawObjectStages(canvas, diagnostics, detector, toggles, pose_labels);
  }
  if (toggles.poses) DrawPoses(canvas, result.detections, detector, capture.camera);
  return canvas;
}

}  // namespace layermod
