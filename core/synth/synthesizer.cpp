// SPDX-License-Identifier: MIT
#include "synth/synthesizer.h"

#include <algorithm>
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

// Places clutter until the target stays visible enough; after kLayoutAttempts layouts, removes
// the worst occluders of the last one instead. Half of the images also ask for a partly hidden
// target during the first kOcclusionAttempts layouts (where the camera allows it: from high
// above, nothing standing on the table hides much). Returns the composited render.
SceneRender PlaceVisibleClutter(SceneLayout& layout, const Backdrop& backdrop,
                                const SynthContext& context, std::mt19937_64& rng) {
  const SynthOptions& options = context.options;
  const bool want_occlusion =
      options.clutter > 0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < 0.5;
  SceneRender alone;  // the target and the backdrop, rendered once
  RenderScene(layout, backdrop, options.camera, alone);
  SceneRender render;
  for (int attempt = 0; attempt < kLayoutAttempts; ++attempt) {
    PlaceClutter(layout, context.models, options, rng);
    render = SceneRender{};
    render.item_views.push_back(alone.item_views.front());
    render.backdrop = alone.backdrop;
    RenderScene(layout, backdrop, options.camera, render);
    const double visible = VisibleFraction(render, 0);
    const bool occluded_enough =
        !want_occlusion || attempt >= kOcclusionAttempts || visible <= kOccludedVisibility;
    if (visible >= options.min_target_visibility && occluded_enough) return render;
  }
  while (VisibleFraction(render, 0) < options.min_target_visibility) {
    const std::size_t worst = WorstOccluder(render);
    if (worst == 0) break;  // nothing left to remove
    layout.items.erase(layout.items.begin() + static_cast<std::ptrdiff_t>(worst));
    render.item_views.erase(render.item_views.begin() + static_cast<std::ptrdiff_t>(worst));
    Composite(render);
  }
  return render;
}

std::string TooLargeMessage(const SynthModel& model, const SynthOptions& options) {
  std::ostringstream message;
  message << "object " << model.obj_id << " (diameter " << model.info.diameter_mm
          << " mm) does not fit in the " << options.camera.width << "x" << options.camera.height
          << " image at " << options.dmin_mm << ".." << options.dmax_mm
          << " mm; increase the distances";
  return message.str();
}

void FillGroundTruth(const SceneLayout& layout, const SceneRender& render, SynthFrame& result) {
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
    frame.gt_info.push_back(ItemGtInfo(render, i, frame.depth_mm));
  }
  result.clutter_models = static_cast<int>(frame.gt.size()) - 1;
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
  PaintBackdrop(layout, backdrop, render);

  SynthFrame result;
  BopFrame& frame = result.frame;
  frame.scene_id = kSceneId;
  frame.image_id = index;
  frame.camera = options.camera;
  frame.depth_mm = ApplyDepthSensorModel(render.depth_mm, options.camera, options.noise, rng);
  frame.color = ApplyColorSensorModel(render.color, options.noise, rng);
  FillGroundTruth(layout, render, result);
  result.clean_depth_mm = render.depth_mm;
  result.item_index = render.item_index;
  result.target_distance_mm = layout.camera.distance_mm;
  result.target_visibility = frame.gt_info.front().visib_fract;
  return result;
}

}  // namespace layermod
