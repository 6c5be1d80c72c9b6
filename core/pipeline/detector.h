// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/camera.h"
#include "match/matcher.h"
#include "pose/icp.h"
#include "pose/verification.h"
#include "scene/coarse_positioning.h"
#include "scene/region_division.h"
#include "templates/archive.h"

namespace layermod {

enum class DetectionMode {
  kScenePatch,  // region division -> coarse positioning -> the layer's templates (paper §3.2-3.4)
  kExhaustive,  // every template of every layer over the whole image (original LineMOD)
  kColorOnly,   // LINE-2D: colour gradients only, exhaustive; for captures without depth
};
std::string_view ModeName(DetectionMode mode);
DetectionMode ParseDetectionMode(std::string_view text);  // throws Error

// Whether Scene-Patch matching sets apart what lies in front of the object (match/occluders.h).
enum class OcclusionMode {
  kAware,   // features on occluders are counted out of a template's score
  kIgnore,  // every feature counts (LineMOD as published)
};
std::string_view OcclusionModeName(OcclusionMode mode);
OcclusionMode ParseOcclusionMode(std::string_view text);  // throws Error

struct DetectorOptions {
  DetectionMode mode = DetectionMode::kScenePatch;
  RegionDivisionOptions regions;
  CoarsePositioningOptions coarse;
  MatchOptions match;
  OcclusionMode occlusion = OcclusionMode::kAware;  // see match/occluders.h
  int max_instances = 1;                            // detections kept per object
  int pose_candidates = 12;  // best raw matches per object that get a pose and a verification
  // Detections less confident (pipeline/confidence.h) are not reported. 0.8 keeps precision at
  // or above 98 % with at most 0.2 % of absent parts detected on the sets in docs/RESULTS.md.
  double min_confidence = 0.8;
  IcpOptions icp;
  VerificationOptions verification;

  void Validate() const;  // throws Error
};

// One RGB-D (or RGB) frame. Colour CV_8UC3 BGR; depth CV_32F mm with 0 = invalid, or empty.
struct Capture {
  cv::Mat color;
  cv::Mat depth_mm;
  PinholeCamera camera;
};

struct Detection {
  std::int32_t obj_id = 0;
  std::string name;
  float score = 0.0f;       // LineMOD similarity of the matched template, percent
  double ranking = 0.0;     // what detections are ordered by (RankingScore, RanksHigher), percent
  double confidence = 0.0;  // how likely the pose is right, 0..1 (pipeline/confidence.h)
  Pose cam_from_model;
  std::uint32_t template_id = 0;
  int layer_index = 0;
  double layer_depth_mm = 0.0;
  cv::Point box_tl_px;  // where the template matched (level-0 top-left)
  IcpResult icp;        // iterations == 0 when not refined (no depth)
  Verification verification;
};

// Wall time per stage. Region division and coarse positioning are summed over objects, and
// their per-frame parts run side by side, each counting its own time, so the stages may add up
// to a little more than the total; matching and the pose stage run all objects side by side and
// count the wall time of all of them together.
struct StageTimings {
  double prepare_ms = 0.0;  // quantization, spreading, response maps, linear memories
  double regions_ms = 0.0;  // scene region division
  double coarse_ms = 0.0;   // coarse positioning
  double match_ms = 0.0;    // template matching
  double pose_ms = 0.0;     // initial pose, ICP, verification
  double total_ms = 0.0;
};

// What each stage saw, for overlays and the studio's preview.
struct ObjectDiagnostics {
  std::int32_t obj_id = 0;
  RegionDivision division;  // empty in exhaustive / colour-only mode
  CoarsePositioning coarse;
  std::vector<RawMatch> matches;  // after NMS, before pose verification
};

struct DetectionResult {
  std::vector<Detection> detections;  // best first (RanksHigher), over all objects
  StageTimings timings;
  std::vector<ObjectDiagnostics> diagnostics;
};

// Detects the objects of one or more archives in captures taken with the archives' camera.
class Detector {
 public:
  // Throws Error when archives disagree on the camera or the feature parameters, or an object id
  // appears twice.
  explicit Detector(std::vector<TemplateArchive> archives);
  // The same with archives shared rather than moved in (the public API's archives are shared
  // handles; a detector built from them copies no template).
  explicit Detector(std::vector<std::shared_ptr<const TemplateArchive>> archives);

  // Throws Error for an unusable capture: sizes that differ from the camera, wrong pixel types,
  // intrinsics other than the archives', depth required by the mode but absent.
  DetectionResult Detect(const Capture& capture, const DetectorOptions& options) const;

  // The archives, in the order given (owned or shared, however the detector was built).
  std::vector<const TemplateArchive*> archives() const;
  std::size_t archive_count() const { return archives_.size(); }
  const TemplateArchive& archive(std::size_t index) const { return *archives_.at(index); }
  const PinholeCamera& camera() const { return archives_.front()->camera(); }
  const ArchiveObject& Object(std::int32_t obj_id) const;
  const TemplateArchive& ArchiveOf(std::int32_t obj_id) const;

 private:
  struct ObjectEntry {
    std::size_t archive = 0;
    std::int32_t obj_id = 0;
    std::vector<LayerEdgeRange> edge_ranges;  // per layer
    cv::Size largest_template;                // level-0 px, over all its templates
    RenderMesh pose_mesh;                     // the mesh ICP and verification render
    std::vector<TemplateFacts> facts;         // of TemplatesOf(obj_id), in its order
  };

  void IndexObjects();  // fills objects_ from archives_; throws Error for inconsistent archives
  // How far past the image a scene region may reach: half the largest template of any object, so
  // that a part the border cuts in half can still be matched (PrepareSceneRegion).
  int BorderPaddingPx() const;

  std::shared_ptr<const std::vector<TemplateArchive>> owned_;     // by-value construction only
  std::vector<std::shared_ptr<const TemplateArchive>> archives_;  // into owned_ or shared
  std::vector<ObjectEntry> objects_;
};

}  // namespace layermod
