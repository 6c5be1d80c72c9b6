// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace layermod::api {

// One detected object instance. The pose is cam_from_model, BOP's convention:
// x_cam = R * x_model + t_mm, in mm, camera frame x right, y down, z forward.
struct Detection {
  std::int32_t obj_id = 0;
  std::string name;
  float score = 0.0f;       // LineMOD similarity of the matched template, percent
  double ranking = 0.0;     // what detections are ordered by: score x depth fit^2 x colour, percent
  double confidence = 0.0;  // how likely the pose is right, 0..1 (below min_confidence: dropped)
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t_mm = Eigen::Vector3d::Zero();
  std::uint32_t template_id = 0;  // the matched template's id in its archive
  int layer_index = 0;            // the depth layer of the matched template (paper §3.1)
  double layer_depth_mm = 0.0;    // that layer's camera distance
  int box_x_px = 0;               // top-left of the matched template in the image (level 0)
  int box_y_px = 0;
  // Pose refinement and verification (0 iterations: not refined, e.g. without depth).
  int icp_iterations = 0;
  double icp_rmse_mm = 0.0;
  double icp_inlier_ratio = 0.0;
  double depth_inlier_ratio = 0.0;    // silhouette pixels whose depth agrees with the model
  double depth_fit = 0.0;             // mean closeness of that agreement, 1 = exact
  double visible_ratio = 0.0;         // silhouette pixels the scene does not contradict
  double occluded_ratio = 0.0;        // measured silhouette pixels with the scene in front
  double contradicted_ratio = 0.0;    // measured silhouette pixels with the scene behind
  double surface_continuation = 0.0;  // ring outside the outline where the surface goes on
  double color_agreement = 1.0;       // saturated pixels whose hue matches (1 when not judged)
  double outline_agreement = 0.0;     // outline pixels on a scene edge of their orientation
};

// Wall time per stage of one Detect call, in ms, summed over objects. Region division and
// coarse positioning run side by side, so the stages may add up to a little more than total.
struct Timings {
  double prepare_ms = 0.0;  // quantization, spreading, response maps, linear memories
  double regions_ms = 0.0;  // scene region division (paper §3.2)
  double coarse_ms = 0.0;   // coarse positioning (paper §3.3)
  double match_ms = 0.0;    // template matching
  double pose_ms = 0.0;     // initial pose, ICP, verification
  double total_ms = 0.0;
};

struct DetectionResult {
  std::vector<Detection> detections;  // best first by `ranking`, over all objects
  Timings timings;
  std::string mode;  // the detector mode that produced it ("scene-patch", ...)
};

// The result as `layermod detect --json` writes it (cam_R_m2c row-major, cam_t_m2c mm).
std::string ToJson(const DetectionResult& result, int indent = 2);

}  // namespace layermod::api
