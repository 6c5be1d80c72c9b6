// SPDX-License-Identifier: MIT
#include "pipeline/detection_poses.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "pipeline/confidence.h"
#include "pose/initial_pose.h"

namespace layermod {
namespace {

Detection InitialDetection(const RawMatch& match, const TemplateRecord& tmpl,
                           const ArchiveObject& object, const Capture& capture) {
  Detection detection;
  detection.obj_id = object.obj_id;
  detection.name = object.name;
  detection.score = match.similarity_percent;
  detection.template_id = match.template_id;
  detection.layer_index = tmpl.layer_index;
  detection.layer_depth_mm = tmpl.layer_depth_mm;
  detection.box_tl_px = cv::Point(match.x, match.y);
  double centre_depth_mm = EstimateCentreDepthMm(tmpl, detection.box_tl_px, capture.depth_mm);
  if (centre_depth_mm <= 0.0) centre_depth_mm = tmpl.layer_depth_mm;  // RGB only, or a hole
  detection.cam_from_model = PoseFromMatch(tmpl, detection.box_tl_px, centre_depth_mm,
                                           object.sphere.centre, capture.camera);
  return detection;
}

Detection RefineCandidate(const RawMatch& match, const TemplateArchive& archive,
                          const ArchiveObject& object, const RenderMesh& pose_mesh,
                          const Capture& capture, const GradientLabels& gradients,
                          const DetectorOptions& options) {
  const TemplateRecord& tmpl = archive.templates().at(match.template_id);
  Detection detection = InitialDetection(match, tmpl, object, capture);
  const Pose initial = detection.cam_from_model;
  const auto verify = [&](const Pose& pose) {
    return VerifyPose(pose_mesh, capture.camera, pose, capture.depth_mm, capture.color,
                      options.verification, gradients);
  };
  if (!capture.depth_mm.empty()) {
    detection.icp =
        RefinePoseIcp(pose_mesh, capture.camera, capture.depth_mm, initial, options.icp);
    detection.cam_from_model = detection.icp.cam_from_model;
  }
  detection.verification = verify(detection.cam_from_model);
  if (!detection.verification.accepted && !capture.depth_mm.empty()) {
    // Point-to-plane ICP can slide along a view that is mostly one plane (sensor steps of 1 mm
    // are enough to start it): the template's own pose is kept when it verifies and ICP's does
    // not. The ICP figures stay those of the refinement that was not kept, which lowers the
    // confidence.
    const Verification at_initial = verify(initial);
    if (at_initial.accepted) {
      detection.cam_from_model = initial;
      detection.verification = at_initial;
    }
  }
  return detection;
}

bool SameInstance(const Detection& a, const Detection& b, const ArchiveObject& object) {
  const Eigen::Vector3d centre_a = a.cam_from_model * object.sphere.centre;
  const Eigen::Vector3d centre_b = b.cam_from_model * object.sphere.centre;
  return (centre_a - centre_b).norm() < object.sphere.radius_mm;
}

}  // namespace

double RankingScore(const Detection& detection, bool has_depth) {
  const double fit = has_depth ? detection.verification.depth_fit : 1.0;
  return detection.score * fit * fit * detection.verification.color_agreement;
}

bool RanksHigher(const Detection& a, const Detection& b) {
  const bool likely_a = a.confidence >= kLikelyConfidence;
  const bool likely_b = b.confidence >= kLikelyConfidence;
  if (likely_a != likely_b) return likely_a;
  return a.ranking > b.ranking;
}

std::vector<Detection> PosesFromMatches(const std::vector<RawMatch>& matches,
                                        const TemplateArchive& archive, const ArchiveObject& object,
                                        const RenderMesh& pose_mesh, const Capture& capture,
                                        const GradientLabels& gradients,
                                        const DetectorOptions& options) {
  // The best matches (suppression keeps one per template and place) are refined
  // independently, in parallel: each costs several renders.
  const std::size_t candidates =
      std::min(matches.size(), static_cast<std::size_t>(options.pose_candidates));
  std::vector<Detection> refined(candidates);
  tbb::parallel_for(std::size_t{0}, candidates, [&](std::size_t i) {
    refined[i] =
        RefineCandidate(matches[i], archive, object, pose_mesh, capture, gradients, options);
  });
  std::vector<Detection> verified;
  for (Detection& detection : refined) {
    if (detection.verification.accepted) verified.push_back(std::move(detection));
  }
  const bool has_depth = !capture.depth_mm.empty();
  for (Detection& detection : verified) {
    detection.ranking = RankingScore(detection, has_depth);
    detection.confidence = DetectionConfidence(FeaturesOf(detection), has_depth);
  }
  std::stable_sort(verified.begin(), verified.end(), RanksHigher);
  std::vector<Detection> kept;
  for (Detection& detection : verified) {
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const Detection& other) {
      return SameInstance(other, detection, object);
    });
    if (duplicate) continue;
    kept.push_back(std::move(detection));
    if (static_cast<int>(kept.size()) == options.max_instances) break;
  }
  // The threshold applies to the instances chosen, so that a lower one never stands in for a
  // doubtful best one.
  std::erase_if(kept, [&](const Detection& detection) {
    return detection.confidence < options.min_confidence;
  });
  return kept;
}

}  // namespace layermod
