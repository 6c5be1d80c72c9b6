// SPDX-License-Identifier: MIT
#include "pipeline/detection_json.h"

#include "dataset/bop_json.h"

namespace layermod {

nlohmann::ordered_json DetectionToJson(const Detection& detection) {
  const Verification& verification = detection.verification;
  return {{"obj_id", detection.obj_id},
          {"name", detection.name},
          {"score", detection.score},
          {"ranking", detection.ranking},
          {"confidence", detection.confidence},
          {"cam_R_m2c", bop_internal::RotationJson(detection.cam_from_model.R)},
          {"cam_t_m2c", bop_internal::VectorJson(detection.cam_from_model.t)},
          {"template_id", detection.template_id},
          {"layer_mm", detection.layer_depth_mm},
          {"icp",
           {{"rmse_mm", detection.icp.rmse_mm},
            {"inlier_ratio", detection.icp.inlier_ratio},
            {"iterations", detection.icp.iterations}}},
          {"verification",
           {{"depth_inlier_ratio", verification.depth_inlier_ratio},
            {"depth_fit", verification.depth_fit},
            {"visible_ratio", verification.visible_ratio},
            {"occluded_ratio", verification.occluded_ratio},
            {"contradicted_ratio", verification.contradicted_ratio},
            {"surface_continuation", verification.surface_continuation},
            {"color_agreement", verification.color_agreement},
            {"outline_agreement", verification.outline_agreement}}}};
}

nlohmann::ordered_json StageTimingsToJson(const StageTimings& t) {
  return {{"prepare", t.prepare_ms}, {"regions", t.regions_ms}, {"coarse", t.coarse_ms},
          {"match", t.match_ms},     {"pose", t.pose_ms},       {"total", t.total_ms}};
}

nlohmann::ordered_json DetectionResultToJson(const DetectionResult& result, DetectionMode mode) {
  nlohmann::ordered_json json;
  json["mode"] = std::string(ModeName(mode));
  json["detections"] = nlohmann::ordered_json::array();
  for (const Detection& detection : result.detections) {
    json["detections"].push_back(DetectionToJson(detection));
  }
  json["timings_ms"] = StageTimingsToJson(result.timings);
  return json;
}

}  // namespace layermod
