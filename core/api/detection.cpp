// SPDX-License-Identifier: MIT
#include <layermod/detection.h>

#include "api/detection_convert.h"
#include "pipeline/detection_json.h"

namespace layermod::api {
namespace {

Detection FromCore(const layermod::Detection& core) {
  Detection detection;
  detection.obj_id = core.obj_id;
  detection.name = core.name;
  detection.score = core.score;
  detection.ranking = core.ranking;
  detection.confidence = core.confidence;
  detection.R = core.cam_from_model.R;
  detection.t_mm = core.cam_from_model.t;
  detection.template_id = core.template_id;
  detection.layer_index = core.layer_index;
  detection.layer_depth_mm = core.layer_depth_mm;
  detection.box_x_px = core.box_tl_px.x;
  detection.box_y_px = core.box_tl_px.y;
  detection.icp_iterations = core.icp.iterations;
  detection.icp_rmse_mm = core.icp.rmse_mm;
  detection.icp_inlier_ratio = core.icp.inlier_ratio;
  detection.depth_inlier_ratio = core.verification.depth_inlier_ratio;
  detection.depth_fit = core.verification.depth_fit;
  detection.visible_ratio = core.verification.visible_ratio;
  detection.occluded_ratio = core.verification.occluded_ratio;
  detection.contradicted_ratio = core.verification.contradicted_ratio;
  detection.surface_continuation = core.verification.surface_continuation;
  detection.color_agreement = core.verification.color_agreement;
  detection.outline_agreement = core.verification.outline_agreement;
  return detection;
}

}  // namespace

DetectionResult FromCore(const layermod::DetectionResult& result, DetectionMode mode) {
  DetectionResult converted;
  for (const layermod::Detection& detection : result.detections) {
    converted.detections.push_back(FromCore(detection));
  }
  const StageTimings& t = result.timings;
  converted.timings = {t.prepare_ms, t.regions_ms, t.coarse_ms, t.match_ms, t.pose_ms, t.total_ms};
  converted.mode = std::string(ModeName(mode));
  return converted;
}

layermod::Detection ToCore(const Detection& detection) {
  layermod::Detection core;
  core.obj_id = detection.obj_id;
  core.name = detection.name;
  core.score = detection.score;
  core.ranking = detection.ranking;
  core.confidence = detection.confidence;
  core.cam_from_model = {detection.R, detection.t_mm};
  core.template_id = detection.template_id;
  core.layer_index = detection.layer_index;
  core.layer_depth_mm = detection.layer_depth_mm;
  core.box_tl_px = {detection.box_x_px, detection.box_y_px};
  core.icp.iterations = detection.icp_iterations;
  core.icp.rmse_mm = detection.icp_rmse_mm;
  core.icp.inlier_ratio = detection.icp_inlier_ratio;
  core.verification.depth_inlier_ratio = detection.depth_inlier_ratio;
  core.verification.depth_fit = detection.depth_fit;
  core.verification.visible_ratio = detection.visible_ratio;
  core.verification.occluded_ratio = detection.occluded_ratio;
  core.verification.contradicted_ratio = detection.contradicted_ratio;
  core.verification.surface_continuation = detection.surface_continuation;
  core.verification.color_agreement = detection.color_agreement;
  core.verification.outline_agreement = detection.outline_agreement;
  core.verification.accepted = true;
  return core;
}

std::string ToJson(const DetectionResult& result, int indent) {
  layermod::DetectionResult core;
  for (const Detection& detection : result.detections) core.detections.push_back(ToCore(detection));
  const Timings& t = result.timings;
  core.timings = {t.prepare_ms, t.regions_ms, t.coarse_ms, t.match_ms, t.pose_ms, t.total_ms};
  const DetectionMode mode = ParseDetectionMode(result.mode.empty() ? "scene-patch" : result.mode);
  return DetectionResultToJson(core, mode).dump(indent);
}

}  // namespace layermod::api
