// SPDX-License-Identifier: MIT
#include "eval/evaluation.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "eval/envelope_coverage.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

void CheckSceneExists(const std::vector<BopScene>& scenes, const FrameSelectionOptions& selection,
                      const std::filesystem::path& dataset_dir) {
  if (!selection.scene_id) return;
  for (const BopScene& scene : scenes) {
    if (scene.scene_id == *selection.scene_id) return;
  }
  throw Error(Quoted(dataset_dir) + ": there is no scene " + std::to_string(*selection.scene_id));
}

void CheckDepth(const EvalPlan& plan) {
  for (const EvalFrame& frame : plan.frames) {
    const BopScene& scene = plan.dataset.scenes[frame.scene_index];
    if (!scene.has_depth) {
      throw Error(Quoted(scene.dir) + " has no depth images; this mode needs depth (use the " +
                  "colour-only mode for RGB datasets)");
    }
  }
}

}  // namespace

bool ModeNeedsDepth(DetectionMode mode) { return mode != DetectionMode::kColorOnly; }

EvalPlan PlanEvaluation(const std::filesystem::path& dataset_dir,
                        const std::vector<std::int32_t>& obj_ids,
                        const FrameSelectionOptions& selection, bool needs_depth) {
  selection.Validate();
  EvalPlan plan;
  plan.dataset.dir = dataset_dir;
  plan.dataset.scenes = ListBopScenes(dataset_dir);
  CheckSceneExists(plan.dataset.scenes, selection, dataset_dir);
  plan.frames =
      SelectEvalFrames(plan.dataset.scenes, std::set<std::int32_t>(obj_ids.begin(), obj_ids.end()),
                       selection, dataset_dir);
  if (needs_depth) CheckDepth(plan);
  plan.dataset.models = LoadEvalModels(FindBopModelsDir(dataset_dir), obj_ids);
  return plan;
}

EnvelopeMisses FindEnvelopeMisses(const Detector& detector, const EvalPlan& plan) {
  ObjectEnvelopes envelopes;
  for (std::size_t a = 0; a < detector.archive_count(); ++a) envelopes.Add(detector.archive(a));
  EnvelopeMisses outside;
  for (const EvalFrame& frame : plan.frames) {
    const BopFrameAnnotations& annotations =
        plan.dataset.scenes[frame.scene_index].annotations.at(frame.image_id);
    for (const EvalTarget& target : frame.targets) {
      std::string note;
      bool covered = false;
      for (int index : target.gt_indices) {
        const EnvelopeCheck check =
            envelopes.At(target.obj_id)
                .Check(annotations.gt.at(static_cast<std::size_t>(index)).cam_from_model);
        covered = covered || check.inside;
        if (note.empty()) note = check.reason;
      }
      if (!covered) outside[{frame.scene_id, frame.image_id, target.obj_id}] = note;
    }
  }
  return outside;
}

void MarkEnvelopeMisses(const EnvelopeMisses& misses, MethodRun& run) {
  for (TargetOutcome& outcome : run.outcomes) {
    const auto it = misses.find({outcome.scene_id, outcome.image_id, outcome.obj_id});
    if (it == misses.end()) continue;
    outcome.outside_envelope = true;
    outcome.envelope_note = it->second;
  }
}

EvalMethod DetectorMethod(const Detector& detector, const DetectorOptions& options) {
  return {std::string(ModeName(options.mode)), [&detector, options](const BopFrame& frame) {
            return detector.Detect(Capture{frame.color, frame.depth_mm, frame.camera}, options)
                .detections;
          }};
}

std::vector<std::int32_t> DetectorObjectIds(const Detector& detector) {
  std::vector<std::int32_t> ids;
  for (const TemplateArchive* archive : detector.archives()) {
    for (const ArchiveObject& object : archive->manifest().objects) ids.push_back(object.obj_id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

Evaluation Evaluate(const Detector& detector, const DetectorOptions& options,
                    const std::filesystem::path& dataset_dir,
                    const FrameSelectionOptions& selection, const EvalMetricOptions& metrics,
                    const JobControl& job) {
  options.Validate();
  metrics.Validate();
  const EvalPlan plan = PlanEvaluation(dataset_dir, DetectorObjectIds(detector), selection,
                                       ModeNeedsDepth(options.mode));
  // The detector reports every detection; the threshold is applied to the outcomes, so that the
  // same run gives the precision-recall curve over all thresholds.
  DetectorOptions unthresholded = options;
  unthresholded.min_confidence = 0.0;
  std::vector<MethodRun> runs = RunMethods(plan.dataset, plan.frames,
                                           {DetectorMethod(detector, unthresholded)}, metrics, job);
  Evaluation evaluation;
  evaluation.run = std::move(runs.front());
  MarkEnvelopeMisses(FindEnvelopeMisses(detector, plan), evaluation.run);
  evaluation.summary = Summarize(evaluation.run, plan.dataset.models, options.min_confidence);
  return evaluation;
}

}  // namespace layermod
