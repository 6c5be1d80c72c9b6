// SPDX-License-Identifier: MIT
#include "eval/eval_frames.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

using ImageKey = std::pair<int, int>;  // scene id, image id
using TargetObjects = std::map<ImageKey, std::set<std::int32_t>>;

TargetObjects GroupTargets(const std::vector<BopScene>& scenes,
                           const std::vector<BopTarget>& targets,
                           const std::filesystem::path& dataset_dir) {
  TargetObjects grouped;
  for (const BopTarget& target : targets) {
    bool found = false;
    for (const BopScene& scene : scenes) {
      found = found ||
              (scene.scene_id == target.scene_id && scene.annotations.count(target.image_id) != 0);
    }
    if (!found) {
      throw FormatError("the targets name scene " + std::to_string(target.scene_id) + " image " +
                        std::to_string(target.image_id) + ", which " + Quoted(dataset_dir) +
                        " does not have");
    }
    grouped[{target.scene_id, target.image_id}].insert(target.obj_id);
  }
  return grouped;
}

bool VisibleEnough(const BopFrameAnnotations& frame, std::size_t gt_index, double min_visib) {
  if (frame.gt_info.empty()) return true;
  return frame.gt_info[gt_index].visib_fract >= min_visib;
}

std::vector<EvalTarget> FrameTargets(const BopFrameAnnotations& frame,
                                     const std::set<std::int32_t>& wanted, double min_visib) {
  std::map<std::int32_t, EvalTarget> by_object;
  for (std::size_t i = 0; i < frame.gt.size(); ++i) {
    const std::int32_t obj_id = frame.gt[i].obj_id;
    if (wanted.count(obj_id) == 0 || !VisibleEnough(frame, i, min_visib)) continue;
    EvalTarget& target = by_object[obj_id];
    target.obj_id = obj_id;
    target.gt_indices.push_back(static_cast<int>(i));
  }
  std::vector<EvalTarget> targets;
  for (auto& [obj_id, target] : by_object) targets.push_back(std::move(target));
  return targets;
}

std::vector<std::int32_t> AbsentObjects(const BopFrameAnnotations& frame,
                                        const std::set<std::int32_t>& obj_ids) {
  std::set<std::int32_t> absent = obj_ids;
  for (const BopGroundTruth& gt : frame.gt) absent.erase(gt.obj_id);
  return {absent.begin(), absent.end()};
}

std::set<std::int32_t> Intersect(const std::set<std::int32_t>& a, const std::set<std::int32_t>& b) {
  std::set<std::int32_t> both;
  for (const std::int32_t id : a) {
    if (b.count(id) != 0) both.insert(id);
  }
  return both;
}

}  // namespace

void FrameSelectionOptions::Validate() const {
  if (!(min_visib_fract >= 0.0 && min_visib_fract <= 1.0)) {
    throw Error("the minimum visibility must be in [0, 1]");
  }
  if (max_frames < 0) throw Error("the frame limit must not be negative");
}

std::vector<EvalFrame> SelectEvalFrames(const std::vector<BopScene>& scenes,
                                        const std::set<std::int32_t>& obj_ids,
                                        const FrameSelectionOptions& options,
                                        const std::filesystem::path& dataset_dir) {
  options.Validate();
  const TargetObjects targets = GroupTargets(scenes, options.targets, dataset_dir);
  std::vector<EvalFrame> frames;
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    const BopScene& scene = scenes[s];
    if (options.scene_id && scene.scene_id != *options.scene_id) continue;
    for (const int image_id : scene.image_ids) {
      if (options.max_frames > 0 && static_cast<int>(frames.size()) >= options.max_frames) break;
      std::set<std::int32_t> wanted = obj_ids;
      if (!options.targets.empty()) {
        const auto listed = targets.find({scene.scene_id, image_id});
        if (listed == targets.end()) continue;
        wanted = Intersect(wanted, listed->second);
      }
      const BopFrameAnnotations& annotations = scene.annotations.at(image_id);
      EvalFrame frame{s,
                      scene.scene_id,
                      image_id,
                      FrameTargets(annotations, wanted, options.min_visib_fract),
                      {}};
      if (options.absent_objects) frame.absent = AbsentObjects(annotations, obj_ids);
      if (!frame.targets.empty() || !frame.absent.empty()) frames.push_back(std::move(frame));
    }
  }
  const bool any_target = std::any_of(
      frames.begin(), frames.end(), [](const EvalFrame& frame) { return !frame.targets.empty(); });
  if (!any_target) {
    char visibility[32];
    std::snprintf(visibility, sizeof visibility, "%.2f", options.min_visib_fract);
    throw Error(Quoted(dataset_dir) +
                ": no frame shows an object of the archives with visibility " + "of at least " +
                visibility);
  }
  return frames;
}

}  // namespace layermod
