// SPDX-License-Identifier: MIT
#include "eval/eval_runner.h"

#include <chrono>
#include <limits>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

const Detection* BestDetectionOf(const std::vector<Detection>& detections, std::int32_t obj_id) {
  for (const Detection& detection : detections) {
    if (detection.obj_id == obj_id) return &detection;
  }
  return nullptr;
}

const EvalModel& ModelOf(const std::map<std::int32_t, EvalModel>& models, std::int32_t obj_id) {
  const auto it = models.find(obj_id);
  if (it == models.end()) throw Error("no model for object " + std::to_string(obj_id));
  return it->second;
}

PoseScore ClosestInstanceScore(const EvalTarget& target, const BopFrame& image,
                               const EvalModel& model, const Pose& estimated,
                               const EvalMetricOptions& options) {
  PoseScore best;
  best.error_mm = std::numeric_limits<double>::infinity();
  for (const int gt_index : target.gt_indices) {
    const Pose& truth = image.gt.at(static_cast<std::size_t>(gt_index)).cam_from_model;
    const PoseScore score = ScorePose(model, estimated, truth, image.camera, options);
    if (score.error_mm < best.error_mm) best = score;
  }
  return best;
}

TargetOutcome FrameOutcome(const EvalFrame& frame, std::int32_t obj_id, double frame_time_ms) {
  TargetOutcome outcome;
  outcome.scene_id = frame.scene_id;
  outcome.image_id = frame.image_id;
  outcome.obj_id = obj_id;
  outcome.frame_time_ms = frame_time_ms;
  return outcome;
}

void NoteDetection(const Detection& detection, TargetOutcome& outcome) {
  outcome.detected = true;
  outcome.score = detection.score;
  outcome.confidence = detection.confidence;
  outcome.features = FeaturesOf(detection);
}

double TimedMs(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::vector<TargetOutcome> ScoreFrame(const EvalFrame& frame, const BopFrame& image,
                                      const std::vector<Detection>& detections,
                                      const std::map<std::int32_t, EvalModel>& models,
                                      const EvalMetricOptions& options, double frame_time_ms) {
  std::vector<TargetOutcome> outcomes;
  for (const EvalTarget& target : frame.targets) {
    TargetOutcome outcome = FrameOutcome(frame, target.obj_id, frame_time_ms);
    const EvalModel& model = ModelOf(models, target.obj_id);
    if (const Detection* detection = BestDetectionOf(detections, target.obj_id)) {
      NoteDetection(*detection, outcome);
      outcome.pose = ClosestInstanceScore(target, image, model, detection->cam_from_model, options);
    }
    outcomes.push_back(outcome);
  }
  for (const std::int32_t obj_id : frame.absent) {
    TargetOutcome outcome = FrameOutcome(frame, obj_id, frame_time_ms);
    outcome.present = false;
    if (const Detection* detection = BestDetectionOf(detections, obj_id)) {
      NoteDetection(*detection, outcome);
    }
    outcomes.push_back(outcome);
  }
  return outcomes;
}

std::vector<MethodRun> RunMethods(const EvalDataset& dataset, const std::vector<EvalFrame>& frames,
                                  const std::vector<EvalMethod>& methods,
                                  const EvalMetricOptions& options, const JobControl& job) {
  options.Validate();
  std::vector<MethodRun> runs;
  for (const EvalMethod& method : methods) runs.push_back(MethodRun{method.name, {}, {}});
  for (std::size_t f = 0; f < frames.size(); ++f) {
    job.ThrowIfCancelled();
    job.Report(f, frames.size(), "evaluating");
    const EvalFrame& frame = frames[f];
    const BopFrame image = LoadBopFrame(dataset.scenes.at(frame.scene_index), frame.image_id);
    for (std::size_t m = 0; m < methods.size(); ++m) {
      std::vector<Detection> detections;
      const double time_ms = TimedMs([&] { detections = methods[m].detect(image); });
      runs[m].frame_times_ms.push_back(time_ms);
      for (TargetOutcome& outcome :
           ScoreFrame(frame, image, detections, dataset.models, options, time_ms)) {
        runs[m].outcomes.push_back(outcome);
      }
    }
  }
  job.Report(frames.size(), frames.size(), "evaluating");
  return runs;
}

}  // namespace layermod
