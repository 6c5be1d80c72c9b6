// SPDX-License-Identifier: MIT
#pragma once

// Runs one or more pose estimation methods over the same frames, side by side (each frame is
// loaded once and handed to every method in turn), and judges their best detection per target.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "dataset/bop.h"
#include "eval/eval_frames.h"
#include "eval/eval_model.h"
#include "eval/pose_scoring.h"
#include "pipeline/confidence.h"
#include "pipeline/detector.h"
#include "util/job.h"

namespace layermod {

struct EvalDataset {
  std::filesystem::path dir;
  std::vector<BopScene> scenes;
  std::map<std::int32_t, EvalModel> models;  // every object an EvalFrame may name
};

// A method under test: detections of one frame, best first per object. Only the call is timed.
struct EvalMethod {
  std::string name;
  std::function<std::vector<Detection>(const BopFrame&)> detect;
};

// One target of one frame as one method saw it.
struct TargetOutcome {
  int scene_id = 0;
  int image_id = 0;
  std::int32_t obj_id = 0;
  // false: the frame does not show the object at all (EvalFrame::absent); a detection of it is
  // a false one.
  bool present = true;
  bool detected = false;  // the method returned a detection of this object
  float score = 0.0f;     // of that detection
  double confidence = 0.0;
  ConfidenceFeatures features;  // of that detection, for calibrating the confidence
  PoseScore pose;               // against the closest annotated instance; meaningful when detected
  double frame_time_ms = 0.0;
  // No annotated instance of the target lies inside the archive's view envelope
  // (eval/envelope_coverage.h): every template is more than a sampling step from it, so none
  // matches it closely (ICP may still turn a near template's pose onto it).
  bool outside_envelope = false;
  std::string envelope_note;  // why, for the first instance
};

struct MethodRun {
  std::string name;
  std::vector<TargetOutcome> outcomes;  // frame order, then ascending obj_id
  std::vector<double> frame_times_ms;   // one per frame
};

// Judges the first detection of each target's object against each of the target's annotated
// instances and keeps the closest (smallest ADD/ADD-S); notes the first detection of each absent
// object (then present = false). Throws Error when a target's object is
// not in `models`.
std::vector<TargetOutcome> ScoreFrame(const EvalFrame& frame, const BopFrame& image,
                                      const std::vector<Detection>& detections,
                                      const std::map<std::int32_t, EvalModel>& models,
                                      const EvalMetricOptions& options, double frame_time_ms);

// Every method on every frame (progress per frame; throws Cancelled between frames). Errors of
// the frame loader (missing image, unreadable depth) and of the methods propagate.
std::vector<MethodRun> RunMethods(const EvalDataset& dataset, const std::vector<EvalFrame>& frames,
                                  const std::vector<EvalMethod>& methods,
                                  const EvalMetricOptions& options, const JobControl& job = {});

}  // namespace layermod
