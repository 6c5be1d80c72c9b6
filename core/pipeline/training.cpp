// SPDX-License-Identifier: MIT
#include "pipeline/training.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <limits>
#include <sstream>

#include "features/extraction.h"
#include "features/template_edges.h"
#include "mesh/decimation.h"
#include "render/rasterizer.h"
#include "util/error.h"
#include "util/log.h"
#include "util/version.h"

namespace layermod {
namespace {

constexpr std::size_t kMaxTrainingBytes = std::size_t{8} << 30;

std::string MiB(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

void RefuseOversizedRun(std::size_t templates, const FeatureOptions& features) {
  const std::size_t needed = EstimatedTemplateBytes(templates, features);
  const std::size_t limit = TrainingMemoryLimitBytes();
  if (templates <= 0xFFFFFFFFu && needed <= limit) return;
  throw Error("training: " + std::to_string(templates) + " templates would need about " +
              MiB(needed) + " of memory, more than the " + MiB(limit) +
              " a run may use on this machine; reduce the depth range or the view sampling");
}

float MedianDepthMm(const RenderedView& view) {
  std::vector<float> depths;
  depths.reserve(static_cast<std::size_t>(view.mask.total()));
  for (int y = 0; y < view.depth_mm.rows; ++y) {
    const float* row = view.depth_mm.ptr<float>(y);
    for (int x = 0; x < view.depth_mm.cols; ++x) {
      if (row[x] > 0.0f) depths.push_back(row[x]);
    }
  }
  if (depths.empty()) return 0.0f;
  auto middle = depths.begin() + static_cast<std::ptrdiff_t>(depths.size() / 2);
  std::nth_element(depths.begin(), middle, depths.end());
  return *middle;
}

struct TemplateContext {
  const RenderMesh& mesh;
  const Model& model;
  const TrainingRequest& request;
  float edge_threshold_mm;
};

TemplateRecord TrainOneTemplate(const TemplateContext& context, std::uint16_t layer_index,
                                double layer_depth_mm, const ViewAngles& view) {
  const PinholeCamera& camera = context.request.camera;
  const FeatureOptions& features = context.request.profile.features;
  TemplateRecord record;
  record.obj_id = context.request.obj_id;
  record.layer_index = layer_index;
  record.layer_depth_mm = static_cast<float>(layer_depth_mm);
  record.view = view;
  record.cam_from_model = CamFromModelForView(view, context.model.sphere.centre, layer_depth_mm,
                                              context.request.profile.views.upright_from_model);

  const RenderedView rendered = RenderView(context.mesh, camera, record.cam_from_model);
  const ExtractedTemplate extracted = ExtractTemplate(rendered, camera, features);
  record.levels = extracted.levels;
  record.bbox_px = extracted.bbox_px;
  const cv::Point2d centre_px(camera.cx, camera.cy);  // the sphere centre is on the optical axis
  record.centre_offset_px = cv::Point2f(static_cast<float>(centre_px.x - extracted.bbox_px.x),
                                        static_cast<float>(centre_px.y - extracted.bbox_px.y));
  record.centre_minus_surface_mm = static_cast<float>(layer_depth_mm) - MedianDepthMm(rendered);
  // Seen from above, the part stands on its support plane (model z = bbox min, +Z up), as in a
  // scene; from below the horizon there is no plane to see.
  const SupportPlane support{record.cam_from_model, context.model.bbox_min.z()};
  record.depth_edge_count = TemplateDepthEdgeCount(
      rendered, camera, centre_px, context.model.DiameterMm(), layer_depth_mm,
      context.edge_threshold_mm, view.elevation_deg > 0.0 ? &support : nullptr);
  const bool weak = rendered.empty() || extracted.FeatureCount(0) < features.min_features;
  record.status = weak ? TemplateStatus::kTooFewFeatures : TemplateStatus::kOk;
  return record;
}

RenderMesh RenderMeshFor(const Model& model, const TrainingRequest& request) {
  if (request.max_render_triangles == 0 || model.mesh.n_faces() <= request.max_render_triangles) {
    return ToRenderMesh(model);
  }
  Model simplified = model;
  simplified.mesh =
      DecimateMesh(model.mesh, request.max_render_triangles, request.max_simplification_error_mm);
  LogInfo("rendering a simplified mesh: " + std::to_string(simplified.mesh.n_faces()) + " of " +
          std::to_string(model.mesh.n_faces()) + " triangles");
  return ToRenderMesh(simplified);
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

ArchiveObject DescribeObject(const Model& model, const RenderMesh& mesh,
                             const TrainingRequest& request, const TrainingPlan& plan) {
  ArchiveObject object;
  object.obj_id = request.obj_id;
  object.name = request.name;
  object.mesh_file = model.source.filename().string();
  object.mesh_hash = model.hash;
  object.units = UnitName(model.source_units);
  object.sphere = model.sphere;
  object.diameter_mm = model.DiameterMm();
  object.bbox_min = model.bbox_min;
  object.bbox_size = model.bbox_max - model.bbox_min;
  object.layer_depths_mm = plan.layer_depths_mm;
  object.profile = request.profile;
  object.mesh = mesh;
  return object;
}

void LogWeakTemplates(const std::vector<TemplateRecord>& templates, std::size_t weak) {
  if (weak == 0) return;
  std::ostringstream message;
  message << weak << " template(s) have fewer features than min_features and are kept but "
          << "skipped by the matcher; first ids:";
  int listed = 0;
  for (const TemplateRecord& record : templates) {
    if (record.status != TemplateStatus::kTooFewFeatures) continue;
    message << ' ' << record.id;
    if (++listed == 10) break;
  }
  LogWarning(message.str());
}

}  // namespace

void TrainingRequest::Validate() const {
  camera.Validate();
  profile.Validate();
  if (threads < 0) throw Error("threads: must be 0 (all) or positive");
  if (obj_id < 0) throw Error("obj-id: must be non-negative");
  if (!(max_simplification_error_mm > 0.0)) {
    throw Error("simplification error: must be positive (mm)");
  }
}

std::size_t EstimatedTemplateBytes(std::size_t templates, const FeatureOptions& features) {
  const std::size_t features_per_template =
      static_cast<std::size_t>(features.color_features + features.normal_features) * 2;
  const std::size_t per_template =
      sizeof(TemplateRecord) + 64 + features_per_template * sizeof(Feature);
  if (templates > std::numeric_limits<std::size_t>::max() / per_template) {
    return std::numeric_limits<std::size_t>::max();  // saturate: only compared with a limit
  }
  return templates * per_template;
}

std::size_t TrainingPlan::EstimatedBytes(const FeatureOptions& features) const {
  return EstimatedTemplateBytes(TemplateCount(), features);
}

std::size_t TrainingMemoryLimitBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return kMaxTrainingBytes;
  return std::min(kMaxTrainingBytes,
                  static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size) / 3);
}

TrainingPlan PlanTraining(const Model& model, const TrainingRequest& request) {
  request.Validate();
  TrainingPlan plan;
  plan.radius_mm = model.sphere.radius_mm;
  plan.layer_depths_mm = DepthLayers(request.profile.depth_min_mm, request.profile.depth_max_mm,
                                     model.sphere.radius_mm);
  RefuseOversizedRun(CountViews(request.profile.views) * plan.layer_depths_mm.size(),
                     request.profile.features);
  plan.views = SampleViews(request.profile.views);
  if (plan.views.empty()) throw Error("views: the view ranges produce no view");
  if (plan.layer_depths_mm.front() <= model.sphere.radius_mm) {
    throw Error("depth range: D_min must exceed the sphere radius (camera inside the object)");
  }
  return plan;
}

TrainingResult TrainTemplates(const Model& model, const TrainingRequest& request,
                              const JobControl& job) {
  const auto start = std::chrono::steady_clock::now();
  const TrainingPlan plan = PlanTraining(model, request);
  const std::size_t count = plan.TemplateCount();
  const RenderMesh mesh = RenderMeshFor(model, request);
  const Eigen::Vector3d bbox_size = model.bbox_max - model.bbox_min;
  const TemplateContext context{
      mesh, model, request,
      request.profile.features.depth_edge_fraction * static_cast<float>(bbox_size.maxCoeff())};
  std::vector<TemplateRecord> templates(count);
  std::atomic<std::size_t> done{0};
  const std::size_t view_count = plan.views.size();
  tbb::task_arena arena(request.threads > 0 ? request.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 8), [&](const auto& range) {
      job.ThrowIfCancelled();
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const auto layer = static_cast<std::uint16_t>(i / view_count);
        templates[i] = TrainOneTemplate(context, layer, plan.layer_depths_mm[layer],
                                        plan.views[i % view_count]);
        templates[i].id = static_cast<std::uint32_t>(i);
      }
      job.Report(done += range.size(), count, "training templates");
    });
  });
  job.ThrowIfCancelled();

  TrainingResult result;
  result.summary.radius_mm = plan.radius_mm;
  result.summary.layers = static_cast<int>(plan.layer_depths_mm.size());
  result.summary.templates = count;
  result.summary.weak_templates = static_cast<std::size_t>(
      std::count_if(templates.begin(), templates.end(), [](const TemplateRecord& record) {
        return record.status == TemplateStatus::kTooFewFeatures;
      }));
  LogWeakTemplates(templates, result.summary.weak_templates);

  ArchiveManifest manifest;
  manifest.tool_version = ToolVersion();
  manifest.created_utc = UtcNow();
  manifest.camera = request.camera;
  manifest.objects.push_back(DescribeObject(model, mesh, request, plan));
  result.archive = TemplateArchive(std::move(manifest), std::move(templates));
  result.summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace layermod
