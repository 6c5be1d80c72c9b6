// SPDX-License-Identifier: MIT
#include "synth/synthesizer.h"

#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "synth/backdrop.h"
#include "synth/scene_layout.h"
#include "synth/scene_render.h"
#include "synth/sensor_noise.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr int kLayoutAttempts = 8;     // clutter layouts tried before occluders are removed
constexpr int kOcclusionAttempts = 5;  // of those, how many may insist on some occlusion
constexpr double kOccludedVisibility = 0.95;
constexpr int kSightOccluderAttempts = 12;
constexpr int kSceneId = 1;

// The image's own generator: seeded by (seed, index) through seed_seq, whose algorithm the
// standard fixes, so a dataset is the same on every platform and thread count.
std::mt19937_64 FrameRng(std::uint64_t seed, int index) {
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                         static_cast<std::uint32_t>(index)};
  return std::mt19937_64(sequence);
}

// The clutter item hiding most of the target, or 0 when none does.
std::size_t WorstOccluder(const SceneRender& render) {
  std::vector<int> hidden(render.item_views.size(), 0);
  const cv::Mat& silhouette = render.item_views.front().mask;
  for (int y = 0; y < silhouette.rows; ++y) {
    for (int x = 0; x < silhouette.cols; ++x) {
      const short index = render.item_index.at<short>(y, x);
      if (silhouette.at<uchar>(y, x) != 0 && index > 0) ++hidden[static_cast<std::size_t>(index)];
    }
  }
  const auto worst = std::max_element(hidden.begin(), hidden.end());
  return *worst > 0 ? static_cast<std::size_t>(worst - hidden.begin()) : 0;
}

SceneRender RenderWithClutter(SceneLayout& layout, const Backdrop& backdrop,
                              const SceneRender& alone, const PinholeCamera& camera) {
  SceneRender render;
  render.item_views.push_back(alone.item_views.front());
  render.backdrop = alone.backdrop;
  RenderScene(layout, backdrop, camera, render);
  return render;
}

double VisibilityMiss(double visible, const SynthOptions& options) {
  if (visible > options.max_target_visibility) return visible - options.max_target_visibility;
  return std::max(0.0, options.min_target_visibility - visible);
}

void PlaceRandomSightOccluder(SceneLayout& layout, std::mt19937_64& rng) {
  const double cover = std::uniform_real_distribution<double>(0.1, 0.7)(rng);
  PlaceSightOccluder(layout, cover, rng);
}

// Adds an occluder in the line of sight so that the target is hidden enough (at most
// max_target_visibility visible, at least min_target_visibility). Tries several; when none lands
// in the range, the one closest to it (re-placed from the generator state it was drawn with).
SceneRender OccludeInLineOfSight(SceneLayout& layout, const Backdrop& backdrop,
                                 const SceneRender& alone, const SynthOptions& options,
                                 std::mt19937_64& rng) {
  double best_miss = std::numeric_limits<double>::max();
  std::mt19937_64 best_state = rng;
  for (int attempt = 0; attempt < kSightOccluderAttempts; ++attempt) {
    const std::mt19937_64 state = rng;
    PlaceRandomSightOccluder(layout, rng);
    SceneRender render = RenderWithClutter(layout, backdrop, alone, options.camera);
    const double miss = VisibilityMiss(VisibleFraction(render, 0), options);
    if (miss == 0.0) return render;
    layout.items.pop_back();
    layout.primitives.pop_back();
    if (miss < best_miss) {
      best_miss = miss;
      best_state = state;
    }
  }
  rng = best_state;
  PlaceRandomSightOccluder(layout, rng);
  return RenderWithClutter(layout, backdrop, alone, options.camera);
}

// Places clutter until the target stays visible enough; after kLayoutAttempts layouts, removes
// the worst occluders of the last one instead. Half of the images (every image when
// max_target_visibility < 1) also ask for a partly hidden target during the first
// kOcclusionAttempts layouts (where the camera allows it: from high above, nothing standing on
// the table hides much; with max_target_visibility < 1 an occluder in the line of sight then
// does). Returns the composited render.
SceneRender PlaceVisibleClutter(SceneLayout& layout, const Backdrop& backdrop,
                                const SynthContext& context, std::mt19937_64& rng) {
  const SynthOptions& options = context.options;
  const bool insist = options.max_target_visibility < 1.0;
  const bool want_occlusion =
      insist ||
      (options.clutter > 0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.5);
  const double occluded_visibility = insist ? options.max_target_visibility : kOccludedVisibility;
  SceneRender alone;  // the target and the backdrop, rendered once
  RenderScene(layout, backdrop, options.camera, alone);
  SceneRender render;
  for (int attempt = 0; attempt < kLayoutAttempts; ++attempt) {
    PlaceClutter(layout, context.models, options, rng);
    render = RenderWithClutter(layout, backdrop, alone, options.camera);
    const double visible = VisibleFraction(render, 0);
    const bool occluded_enough = !want_occlusion || (!insist && attempt >= kOcclusionAttempts) ||
                                 visible <= occluded_visibility;
    if (visible >= options.min_target_visibility && occluded_enough) return render;
  }
  while (VisibleFraction(render, 0) < options.min_target_visibility) {
    const std::size_t worst = WorstOccluder(render);
    if (worst == 0) break;  // nothing left to remove
    layout.items.erase(layout.items.begin() + static_cast<std::ptrdiff_t>(worst));
    render.item_views.erase(render.item_views.begin() + static_cast<std::ptrdiff_t>(worst));
    Composite(render);
  }
  if (insist && VisibleFraction(render, 0) > options.max_target_visibility) {
    return OccludeInLineOfSight(layout, backdrop, alone, options, rng);
  }
  return render;
}

// An image without the target: every instance of it is taken out of the layout and the render.
void RemoveTarget(SceneLayout& layout, SceneRender& render) {
  const std::int32_t target_id = layout.items.front().obj_id;
  for (std::size_t i = layout.items.size(); i-- > 0;) {
    if (layout.items[i].obj_id != target_id) continue;
    layout.items.erase(layout.items.begin() + static_cast<std::ptrdiff_t>(i));
    render.item_views.erase(render.item_views.begin() + static_cast<std::ptrdiff_t>(i));
  }
  Composite(render);
}

std::string TooLargeMessage(const SynthModel& model, const SynthOptions& options) {
  std::ostringstream message;
  message << "object " << model.obj_id << " (diameter " << model.info.diameter_mm
          << " mm) does not fit in the " << options.camera.width << "x" << options.camera.height
          << " image at " << options.dmin_mm << ".." << options.dmax_mm
          << " mm; increase the distances";
  return message.str();
}

void FillGroundTruth(const SceneLayout& layout, const SceneRender& render,
                     const PinholeCamera& camera, SynthFrame& result) {
  BopFrame& frame = result.frame;
  for (std::size_t i = 0; i < layout.items.size(); ++i) {
    const PlacedItem& item = layout.items[i];
    if (item.obj_id == 0) {
      ++result.primitives;
      continue;
    }
    BopGroundTruth gt;
    gt.obj_id = item.obj_id;
    gt.cam_from_model = layout.camera.cam_from_world * item.world_from_item;
    frame.gt.push_back(gt);
    frame.gt_info.push_back(
        ItemGtInfo(render, i, ItemWholeSilhouette(layout, camera, i), frame.depth_mm));
  }
  result.clutter_models = 0;
  for (const BopGroundTruth& gt : frame.gt) result.clutter_models += gt.obj_id != result.target_id;
}

}  // namespace

SynthContext PrepareSynthesis(const SynthOptions& options) {
  options.Validate();
  SynthContext context;
  context.options = options;
  const auto files = ModelFilesFor(options.models_dir, options.obj_ids);
  std::set<std::int32_t> ids(options.obj_ids.begin(), options.obj_ids.end());
  if (options.clutter > 0) {
    for (const auto& [obj_id, path] : files) ids.insert(obj_id);
  }
  if (!options.backgrounds_dir.empty()) {
    context.backgrounds = ListBackgroundImages(options.backgrounds_dir);
  }
  context.models =
      LoadSynthModels(options.models_dir, files, std::vector<std::int32_t>(ids.begin(), ids.end()));
  return context;
}

SynthFrame SynthesizeFrame(const SynthContext& context, int index) {
  const SynthOptions& options = context.options;
  std::mt19937_64 rng = FrameRng(options.seed, index);
  const std::int32_t target_id =
      options.obj_ids[static_cast<std::size_t>(index) % options.obj_ids.size()];
  const SynthModel& target = context.models.at(target_id);

  SceneLayout layout;
  layout.items.push_back(PlaceRandomUpright(target.mesh, target.sphere, target_id,
                                            Eigen::Vector2d::Zero(), options, rng));
  const std::optional<CameraSample> camera =
      SampleCamera(layout.items.front(), options.camera, options, rng);
  if (!camera) throw Error(TooLargeMessage(target, options));
  layout.camera = *camera;
  SampleLight(layout, rng);
  SampleTable(layout, rng);
  const Backdrop backdrop = MakeBackdrop(layout.table_extent, layout.items.front().footprint_centre,
                                         layout.camera.centre_in_world, context.backgrounds, rng);
  SceneRender render = PlaceVisibleClutter(layout, backdrop, context, rng);
  // Drawn only when asked for, so that sets without absent images stay as they were.
  const bool absent = options.absent_fraction > 0.0 && std::uniform_real_distribution<double>(
                                                           0.0, 1.0)(rng) < options.absent_fraction;
  if (absent) RemoveTarget(layout, render);
  PaintBackdrop(layout, backdrop, render);

  SynthFrame result;
  BopFrame& frame = result.frame;
  frame.scene_id = kSceneId;
  frame.image_id = index;
  frame.camera = options.camera;
  frame.depth_mm = ApplyDepthSensorModel(render.depth_mm, options.camera, options.noise, rng);
  frame.color = ApplyColorSensorModel(render.color, options.noise, rng);
  result.target_id = target_id;
  FillGroundTruth(layout, render, options.camera, result);
  result.clean_depth_mm = render.depth_mm;
  result.item_index = render.item_index;
  result.target_distance_mm = layout.camera.distance_mm;
  result.target_present = !absent;
  result.target_visibility = absent ? 0.0 : frame.gt_info.front().visib_fract;
  return result;
}

}  // namespace layermod
