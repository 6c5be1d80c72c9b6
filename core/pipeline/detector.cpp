// SPDX-License-Identifier: MIT
#include "pipeline/detector.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "features/depth_edges.h"
#include "match/occluders.h"
#include "mesh/vertex_clustering.h"
#include "pipeline/detection_poses.h"
#include "pipeline/layer_occluders.h"
#include "pipeline/scene_preparation.h"
#include "util/error.h"

namespace layermod {
namespace {

using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

bool SameIntrinsics(const PinholeCamera& a, const PinholeCamera& b) {
  auto close = [](double x, double y) {
    return std::abs(x - y) <= 1e-3 * std::max(1.0, std::abs(y));
  };
  return a.width == b.width && a.height == b.height && close(a.fx, b.fx) && close(a.fy, b.fy) &&
         close(a.cx, b.cx) && close(a.cy, b.cy);
}

// Parameters the scene is quantized with must be the same for every object matched on it: what
// differs between `a` and `b`, for the detector's error, or "" when nothing does.
std::string SceneFeatureDifference(const FeatureOptions& a, const FeatureOptions& b) {
  if (a.normal_frame != b.normal_frame) {
    return "archives quantize depth normals in different frames (format 2 and older in the "
           "camera's, format 3 in each pixel's viewing ray's); retrain the older ones with this "
           "version";
  }
  const bool same = a.pyramid_levels == b.pyramid_levels && a.spread_px == b.spread_px &&
                    a.weak_gradient == b.weak_gradient &&
                    a.max_normal_depth_step_mm == b.max_normal_depth_step_mm;
  return same ? ""
              : "archives use different feature parameters (pyramid, spread, thresholds); train "
                "them with the same profile features";
}

std::vector<LayerEdgeRange> EdgeRanges(const TemplateArchive& archive,
                                       const ArchiveObject& object) {
  std::vector<LayerEdgeRange> ranges(object.layer_depths_mm.size());
  for (std::size_t layer = 0; layer < ranges.size(); ++layer) {
    for (const TemplateRecord& tmpl : archive.TemplatesOf(object.obj_id, static_cast<int>(layer))) {
      if (tmpl.status != TemplateStatus::kOk) continue;
      LayerEdgeRange& range = ranges[layer];
      range.n_min =
          range.valid ? std::min(range.n_min, tmpl.depth_edge_count) : tmpl.depth_edge_count;
      range.n_max =
          range.valid ? std::max(range.n_max, tmpl.depth_edge_count) : tmpl.depth_edge_count;
      range.valid = true;
    }
  }
  return ranges;
}

void ValidateCapture(const Capture& capture, const PinholeCamera& archive_camera,
                     DetectionMode mode) {
  if (capture.color.empty()) throw Error("capture: no colour image");
  if (capture.color.type() != CV_8UC3) throw Error("capture: colour must be 8-bit, 3 channels");
  if (capture.color.cols != capture.camera.width || capture.color.rows != capture.camera.height) {
    throw Error("capture: colour image is " + std::to_string(capture.color.cols) + "x" +
                std::to_string(capture.color.rows) + " but the camera is " +
                std::to_string(capture.camera.width) + "x" + std::to_string(capture.camera.height));
  }
  if (!capture.depth_mm.empty()) {
    if (capture.depth_mm.type() != CV_32F) throw Error("capture: depth must be CV_32F mm");
    if (capture.depth_mm.size() != capture.color.size()) {
      throw Error("capture: depth and colour images differ in size");
    }
  } else if (mode != DetectionMode::kColorOnly) {
    throw Error("capture: this mode needs depth; use --mode color-only for RGB-only captures");
  }
  if (!SameIntrinsics(capture.camera, archive_camera)) {
    throw Error(
        "capture: camera intrinsics differ from the archive's (templates were rendered "
        "for another camera); retrain for this camera");
  }
}

// The per-frame maps Scene-Patch's first two steps start from.
struct DepthMaps {
  cv::Mat cell_depth_mm;  // CellMedianDepth
  cv::Mat edge_strength;  // DepthEdgeStrength of the hole-filled depth
};

// Region division and coarse positioning of one object, into `diagnostics`; adds their times
// to `timings`.
void DivideAndPosition(const ArchiveObject& object, const std::vector<LayerEdgeRange>& edge_ranges,
                       const DepthMaps& maps, const Capture& capture,
                       const FeatureOptions& features, const DetectorOptions& options,
                       ObjectDiagnostics& diagnostics, StageTimings& timings) {
  auto stage_start = Clock::now();
  diagnostics.division =
      DivideScene(maps.cell_depth_mm, capture.depth_mm.size(), object.layer_depths_mm,
                  object.sphere.radius_mm, options.regions);
  timings.regions_ms += MsSince(stage_start);

  stage_start = Clock::now();
  const float edge_threshold_mm =
      features.depth_edge_fraction * static_cast<float>(object.bbox_size.maxCoeff());
  const cv::Mat edges = DepthEdgeMaskFromStrength(maps.edge_strength, edge_threshold_mm);
  diagnostics.coarse =
      PositionCoarsely(diagnostics.division, capture.depth_mm, edges, capture.camera.fx,
                       object.diameter_mm, edge_ranges, options.coarse);
  timings.coarse_ms += MsSince(stage_start);
}

// Where templates anchored within `radius_px` of some point can put features: a template box
// (at most `largest_template`) around each point, grown by the radius.
cv::Rect ReachOfPoints(const std::vector<cv::Point>& points, const cv::Size& largest_template,
                       int radius_px) {
  cv::Rect reach;
  const cv::Point half(largest_template.width + radius_px, largest_template.height + radius_px);
  for (const cv::Point& point : points) {
    reach |= cv::Rect(point - half, point + half + cv::Point(1, 1));
  }
  return reach;
}

// The search of one layer's templates, with their facts (`object_facts`: TemplateFactsOf the
// object's templates, TemplatesOf(obj_id)).
TemplateSearch LayerSearch(const TemplateArchive& archive, std::int32_t obj_id, int layer,
                           std::span<const TemplateFacts> object_facts) {
  const std::span<const TemplateRecord> templates = archive.TemplatesOf(obj_id, layer);
  const auto first =
      static_cast<std::size_t>(templates.data() - archive.TemplatesOf(obj_id).data());
  return {templates, nullptr, archive.ViewClustersOf(obj_id, layer), nullptr,
          object_facts.subspan(first, templates.size())};
}

// Each kept block's layer (Scene-Patch, paper §3.4) with the detection points that survived in
// its blocks, in pixels of the prepared region at `offset`.
using LayerPoints = std::map<int, std::vector<cv::Point>>;
LayerPoints KeptPointsByLayer(const ObjectDiagnostics& diagnostics, const cv::Point& offset) {
  LayerPoints points_by_layer;
  for (int index : diagnostics.coarse.kept) {
    const BlockCandidates& block = diagnostics.coarse.evaluated[static_cast<std::size_t>(index)];
    const int layer =
        diagnostics.division.blocks[static_cast<std::size_t>(block.block_index)].layer_index;
    std::vector<cv::Point>& points = points_by_layer[layer];
    for (const DetectionPoint& point : block.points) {
      if (point.kept) points.push_back(point.pixel - offset);
    }
  }
  return points_by_layer;
}

// One layer's search of `object` around `points` as the occluder bank sees it.
LayerReach ReachOfLayer(const ArchiveObject& object, int layer,
                        const std::vector<cv::Point>& points, const cv::Size& largest_template,
                        const DetectorOptions& options) {
  return {object.layer_depths_mm[static_cast<std::size_t>(layer)], object.sphere.radius_mm,
          ReachOfPoints(points, largest_template, options.coarse.point_step_px)};
}

// Scene-Patch invocation (paper §3.4): each kept block is matched only with its layer's
// templates, only around its surviving detection points (`points_by_layer`). Blocks of one
// layer share a search, so that no template is scored twice. Occlusion-aware, each layer's
// search sees what lies nearer than the object can be at that layer as occluders (`occluders`,
// empty when occlusion is ignored). `border`: the padding past the image as occluders (nullptr
// when the region has none); a layer without occluders of its own uses it.
std::vector<RawMatch> MatchKeptBlocks(const PreparedRegion& prepared,
                                      const LayerPoints& points_by_layer,
                                      const OccluderBank& occluders, const Occluders* border,
                                      const TemplateArchive& archive, const ArchiveObject& object,
                                      std::span<const TemplateFacts> object_facts,
                                      const cv::Size& largest_template,
                                      const DetectorOptions& options) {
  std::vector<TemplateSearch> searches;
  std::vector<std::optional<Occluders>> layer_occluders(points_by_layer.size());
  searches.reserve(points_by_layer.size());
  for (const auto& [layer, points] : points_by_layer) {
    searches.push_back(LayerSearch(archive, object.obj_id, layer, object_facts));
    searches.back().candidate_points = &points;
    searches.back().occluders = border;
    std::optional<Occluders>& own = layer_occluders[searches.size() - 1];
    own = occluders.ForLayer(ReachOfLayer(object, layer, points, largest_template, options));
    if (own) searches.back().occluders = &*own;
  }
  // Detection points aim at the object's centre, where each template's anchor lies (the
  // projection of its sphere centre): the true centre is within half a step of a point.
  std::vector<RawMatch> matches =
      MatchTemplateGroups(prepared.scene, searches, options.match, options.coarse.point_step_px);
  const cv::Point offset = prepared.region_px.tl();
  for (RawMatch& match : matches) {
    match.x += offset.x;
    match.y += offset.y;
  }
  return matches;
}

// Exhaustive and colour-only invocation: every layer's templates over the whole image, through
// the layer's view tree where it has one (as MatchTemplates over all of them otherwise).
std::vector<RawMatch> MatchEveryLayer(const PreparedRegion& prepared, const Occluders* border,
                                      const TemplateArchive& archive, const ArchiveObject& object,
                                      std::span<const TemplateFacts> object_facts,
                                      const DetectorOptions& options) {
  std::vector<TemplateSearch> searches;
  for (std::size_t layer = 0; layer < object.layer_depths_mm.size(); ++layer) {
    searches.push_back(LayerSearch(archive, object.obj_id, static_cast<int>(layer), object_facts));
    searches.back().occluders = border;
  }
  return MatchTemplateGroups(prepared.scene, searches, options.match);
}

// ICP and verification render the object up to 32 times per frame; at working distance a
// pixel spans 1-2 mm, so a few thousand triangles draw the same depth as the full mesh.
constexpr std::size_t kPoseMeshTriangles = 3000;
constexpr double kPoseMeshFinestCellMm = 0.5;

// The largest level-0 template box of the object.
cv::Size LargestTemplate(const TemplateArchive& archive, const ArchiveObject& object) {
  cv::Size largest;
  for (const TemplateRecord& tmpl : archive.TemplatesOf(object.obj_id)) {
    if (tmpl.levels.empty()) continue;
    largest.width = std::max(largest.width, tmpl.levels[0].width);
    largest.height = std::max(largest.height, tmpl.levels[0].height);
  }
  return largest;
}

// Scene-Patch matching reads the scene only near an object's surviving detection points: within
// a template box of the point, plus the point search radius and a margin for image filtering at
// the region's border. Past the image only half a box: a template's anchor lies near its box's
// centre, and a template reaching farther past the border has too little in the image to match.
cv::Rect ReachOfKeptPoints(const CoarsePositioning& coarse, const cv::Size& largest_template,
                           const cv::Size& image_size, const DetectorOptions& options) {
  constexpr int kFilterMarginPx = 8;
  std::vector<cv::Point> pixels;
  for (const DetectionPoint& point : coarse.KeptPoints()) pixels.push_back(point.pixel);
  const int radius = options.coarse.point_step_px + kFilterMarginPx;
  const cv::Rect image(cv::Point(0, 0), image_size);
  return (ReachOfPoints(pixels, largest_template, radius) & image) |
         ReachOfPoints(pixels, largest_template / 2, radius);
}

}  // namespace

std::string_view ModeName(DetectionMode mode) {
  switch (mode) {
    case DetectionMode::kScenePatch:
      return "scene-patch";
    case DetectionMode::kExhaustive:
      return "exhaustive";
    case DetectionMode::kColorOnly:
      return "color-only";
  }
  return "?";
}

std::string_view OcclusionModeName(OcclusionMode mode) {
  switch (mode) {
    case OcclusionMode::kAware:
      return "aware";
    case OcclusionMode::kIgnore:
      return "ignore";
  }
  return "?";
}

OcclusionMode ParseOcclusionMode(std::string_view text) {
  for (OcclusionMode mode : {OcclusionMode::kAware, OcclusionMode::kIgnore}) {
    if (text == OcclusionModeName(mode)) return mode;
  }
  throw Error("occlusion: expected aware or ignore, got '" + std::string(text) + "'");
}

DetectionMode ParseDetectionMode(std::string_view text) {
  for (DetectionMode mode :
       {DetectionMode::kScenePatch, DetectionMode::kExhaustive, DetectionMode::kColorOnly}) {
    if (text == ModeName(mode)) return mode;
  }
  throw Error("mode: expected scene-patch, exhaustive or color-only, got '" + std::string(text) +
              "'");
}

void DetectorOptions::Validate() const {
  regions.Validate();
  coarse.Validate();
  match.Validate();
  icp.Validate();
  verification.Validate();
  if (max_instances < 1 || pose_candidates < 1) {
    throw Error("detector: max_instances and pose_candidates must be >= 1");
  }
  if (!(min_confidence >= 0.0 && min_confidence <= 1.0)) {
    throw Error("detector: min_confidence must lie in [0, 1]");
  }
}

Detector::Detector(std::vector<TemplateArchive> archives)
    : owned_(std::make_shared<const std::vector<TemplateArchive>>(std::move(archives))) {
  for (const TemplateArchive& archive : *owned_) archives_.emplace_back(owned_, &archive);
  IndexObjects();
}

Detector::Detector(std::vector<std::shared_ptr<const TemplateArchive>> archives)
    : archives_(std::move(archives)) {
  for (const auto& archive : archives_) {
    if (archive == nullptr) throw Error("detector: null archive");
  }
  IndexObjects();
}

std::vector<const TemplateArchive*> Detector::archives() const {
  std::vector<const TemplateArchive*> archives;
  for (const auto& archive : archives_) archives.push_back(archive.get());
  return archives;
}

void Detector::IndexObjects() {
  if (archives_.empty()) throw Error("detector: no archive");
  std::set<std::int32_t> seen;
  const FeatureOptions& reference = archives_.front()->manifest().objects.at(0).profile.features;
  for (std::size_t a = 0; a < archives_.size(); ++a) {
    const TemplateArchive& archive = *archives_[a];
    if (!SameIntrinsics(archive.camera(), camera())) {
      throw Error("detector: archives were trained for different cameras");
    }
    for (const ArchiveObject& object : archive.manifest().objects) {
      if (!seen.insert(object.obj_id).second) {
        throw Error("detector: object id " + std::to_string(object.obj_id) + " appears twice");
      }
      const std::string difference = SceneFeatureDifference(object.profile.features, reference);
      if (!difference.empty()) throw Error("detector: " + difference);
      objects_.push_back(
          {a, object.obj_id, EdgeRanges(archive, object), LargestTemplate(archive, object),
           SimplifyToTriangleCount(object.mesh, kPoseMeshTriangles, kPoseMeshFinestCellMm),
           TemplateFactsOf(archive.TemplatesOf(object.obj_id), reference.spread_px)});
    }
  }
}

int Detector::BorderPaddingPx() const {
  int padding = 0;
  for (const ObjectEntry& entry : objects_) {
    padding =
        std::max({padding, entry.largest_template.width / 2, entry.largest_template.height / 2});
  }
  return padding;
}

const ArchiveObject& Detector::Object(std::int32_t obj_id) const {
  return ArchiveOf(obj_id).Object(obj_id);
}

const TemplateArchive& Detector::ArchiveOf(std::int32_t obj_id) const {
  for (const ObjectEntry& entry : objects_) {
    if (entry.obj_id == obj_id) return *archives_[entry.archive];
  }
  throw Error("detector: no object " + std::to_string(obj_id));
}

DetectionResult Detector::Detect(const Capture& capture, const DetectorOptions& options) const {
  options.Validate();
  ValidateCapture(capture, camera(), options.mode);
  const auto start = Clock::now();
  DetectionResult result;
  const FeatureOptions& features = archives_.front()->manifest().objects.at(0).profile.features;
  const bool scene_patch = options.mode == DetectionMode::kScenePatch;
  Capture used = capture;
  if (options.mode == DetectionMode::kColorOnly) used.depth_mm = cv::Mat();

  result.diagnostics.resize(objects_.size());
  // Scene-Patch grows it around the points coarse positioning keeps; the other modes search
  // the whole image.
  cv::Rect search_region =
      scene_patch ? cv::Rect() : cv::Rect(0, 0, used.color.cols, used.color.rows);
  if (scene_patch) {
    // Region division and coarse positioning need depth only: they run first, so that only
    // the part of the scene they point at is prepared for matching. They start from two
    // per-frame maps, computed side by side: the per-cell depths, and the depth-edge strength
    // with sensor holes filled (only the edge threshold depends on the object).
    DepthMaps maps;
    tbb::parallel_invoke(
        [&] {
          const auto task_start = Clock::now();
          maps.cell_depth_mm = CellMedianDepth(used.depth_mm, options.regions.cell_size_px);
          result.timings.regions_ms += MsSince(task_start);
        },
        [&] {
          const auto task_start = Clock::now();
          maps.edge_strength =
              DepthEdgeStrength(FillDepthHolesFromFar(used.depth_mm, options.coarse.hole_fill_px));
          result.timings.coarse_ms += MsSince(task_start);
        });
    // Then each object's division and positioning, side by side; their times are summed.
    std::vector<StageTimings> object_timings(objects_.size());
    tbb::parallel_for(std::size_t{0}, objects_.size(), [&](std::size_t i) {
      const ObjectEntry& entry = objects_[i];
      DivideAndPosition(archives_[entry.archive]->Object(entry.obj_id), entry.edge_ranges, maps,
                        used, features, options, result.diagnostics[i], object_timings[i]);
    });
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      search_region |= ReachOfKeptPoints(result.diagnostics[i].coarse, objects_[i].largest_template,
                                         used.color.size(), options);
      result.timings.regions_ms += object_timings[i].regions_ms;
      result.timings.coarse_ms += object_timings[i].coarse_ms;
    }
  }

  auto stage_start = Clock::now();
  const PreparedRegion prepared =
      PrepareSceneRegion(used.color, used.depth_mm, used.camera, features, search_region,
                         options.match.simd, BorderPaddingPx());
  // A part the image's border cuts is matched by templates reaching past it: the padding there
  // is hidden, as occluders are (match/occluders.h), so their similarity is that of the
  // features in the image, of which they need MatchOptions::min_visible_share.
  const std::optional<Occluders> border =
      prepared.outside_image.empty()
          ? std::nullopt
          : std::optional<Occluders>(
                MakeOccluders(prepared.scene, prepared.outside_image, kHiddenFeatureScore,
                              cv::Rect(-prepared.region_px.tl(), used.color.size())));
  const Occluders* border_occluders = border ? &*border : nullptr;
  result.timings.prepare_ms = MsSince(stage_start);

  // The objects are matched side by side, then posed side by side: one object's serial steps
  // (ranking, suppression, the last candidates of a parallel loop) overlap another's work. Each
  // stage's time is the wall time of all objects together.
  stage_start = Clock::now();
  std::vector<LayerPoints> points(objects_.size());
  std::vector<LayerReach> reaches;  // of every layer searched, for occlusion-aware matching
  for (std::size_t i = 0; scene_patch && i < objects_.size(); ++i) {
    points[i] = KeptPointsByLayer(result.diagnostics[i], prepared.region_px.tl());
    if (options.occlusion != OcclusionMode::kAware) continue;
    const ArchiveObject& object = archives_[objects_[i].archive]->Object(objects_[i].obj_id);
    for (const auto& [layer, layer_points] : points[i]) {
      reaches.push_back(
          ReachOfLayer(object, layer, layer_points, objects_[i].largest_template, options));
    }
  }
  const OccluderBank occluders = reaches.empty() ? OccluderBank() : OccluderBank(prepared, reaches);
  tbb::parallel_for(std::size_t{0}, objects_.size(), [&](std::size_t i) {
    const ObjectEntry& entry = objects_[i];
    const TemplateArchive& archive = *archives_[entry.archive];
    const ArchiveObject& object = archive.Object(entry.obj_id);
    ObjectDiagnostics& diagnostics = result.diagnostics[i];
    diagnostics.obj_id = entry.obj_id;
    if (prepared.region_px.empty()) return;  // nothing survived coarse positioning: no match
    diagnostics.matches =
        scene_patch
            ? MatchKeptBlocks(prepared, points[i], occluders, border_occluders, archive, object,
                              entry.facts, entry.largest_template, options)
            : MatchEveryLayer(prepared, border_occluders, archive, object, entry.facts, options);
  });
  result.timings.match_ms = MsSince(stage_start);

  stage_start = Clock::now();
  const GradientLabels gradients{prepared.gradient_labels, prepared.region_px.tl()};
  std::vector<std::vector<Detection>> per_object(objects_.size());
  tbb::parallel_for(std::size_t{0}, objects_.size(), [&](std::size_t i) {
    const ObjectEntry& entry = objects_[i];
    const TemplateArchive& archive = *archives_[entry.archive];
    per_object[i] =
        PosesFromMatches(result.diagnostics[i].matches, archive, archive.Object(entry.obj_id),
                         entry.pose_mesh, used, gradients, options);
  });
  result.timings.pose_ms = MsSince(stage_start);
  for (std::vector<Detection>& detections : per_object) {
    for (Detection& detection : detections) result.detections.push_back(std::move(detection));
  }
  std::stable_sort(result.detections.begin(), result.detections.end(), RanksHigher);
  result.timings.total_ms = MsSince(start);
  return result;
}

}  // namespace layermod
