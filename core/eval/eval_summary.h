// SPDX-License-Identifier: MIT
#pragma once

// Per-object and overall figures of one method's run (the rows of the paper's Table 4).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "eval/eval_model.h"
#include "eval/eval_runner.h"
#include "eval/precision_recall.h"

namespace layermod {

struct ObjectSummary {
  std::int32_t obj_id = 0;  // 0: all objects together
  bool symmetric_metric = false;
  double diameter_mm = 0.0;
  int frames = 0;            // targets judged (objects the frame shows)
  int detected = 0;          // accepted detections (confidence at least the threshold) of those
  int correct = 0;           // ADD(-S) <= km * d
  int proj2d_correct = 0;    // Proj2D <= threshold
  int box_correct = 0;       // projected box IoU >= threshold: counts as a 2D detection
  int outside_envelope = 0;  // targets no template of the archive covers
  int absent = 0;            // (frame, object) pairs where the frame does not show the object
  int absent_detected = 0;   // of those, with an accepted detection: false detections
  // Why the targets that are not correct were missed, each counted once, in this order: outside
  // the envelope, then no detection at all, a wrong pose (accepted or not), or a right pose
  // whose confidence is below the threshold. They add up to frames - correct.
  int missed_outside_envelope = 0;
  int missed_undetected = 0;
  int missed_wrong_pose = 0;
  int wrong_pose_accepted = 0;  // of missed_wrong_pose: confident wrong poses
  int missed_below_threshold = 0;

  // Accepted detections that are right, over all accepted ones (on targets and absent pairs);
  // 100 when nothing was accepted.
  double PrecisionPercent() const {
    const int accepted = detected + absent_detected;
    return accepted > 0 ? 100.0 * correct / accepted : 100.0;
  }
  double AbsentDetectedPercent() const {
    return absent > 0 ? 100.0 * absent_detected / absent : 0.0;
  }
  double mean_time_ms = 0.0;
  double median_time_ms = 0.0;

  double AccuracyPercent() const { return Percent(correct); }
  double Proj2DPercent() const { return Percent(proj2d_correct); }
  double DetectionRatePercent() const { return Percent(box_correct); }

 private:
  double Percent(int count) const { return frames > 0 ? 100.0 * count / frames : 0.0; }
};

struct MethodSummary {
  std::string name;
  double min_confidence = 0.0;                // detections below it were not counted as accepted
  std::vector<ObjectSummary> objects;         // ascending obj_id
  ObjectSummary overall;                      // every target counted once
  double mean_object_accuracy_percent = 0.0;  // the paper's "average" row: mean over objects
  int frames = 0;
  double mean_frame_ms = 0.0;
  double median_frame_ms = 0.0;
  double p90_frame_ms = 0.0;
  PrecisionRecallCurve precision_recall;  // over every threshold, from the run's outcomes
};

// The `fraction` quantile (0..1) with linear interpolation between ranks; 0 for no values.
double Quantile(std::vector<double> values, double fraction);

// Outcomes whose confidence is below `min_confidence` count as not detected (for a run whose
// method did not apply the threshold itself).
bool Accepted(const TargetOutcome& outcome, double min_confidence);

MethodSummary Summarize(const MethodRun& run, const std::map<std::int32_t, EvalModel>& models,
                        double min_confidence = 0.0);

}  // namespace layermod
