// SPDX-License-Identifier: MIT
#pragma once

// Per-object and overall figures of one method's run (the rows of the paper's Table 4).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "eval/eval_model.h"
#include "eval/eval_runner.h"

namespace layermod {

struct ObjectSummary {
  std::int32_t obj_id = 0;  // 0: all objects together
  bool symmetric_metric = false;
  double diameter_mm = 0.0;
  int frames = 0;  // targets judged
  int detected = 0;
  int correct = 0;           // ADD(-S) <= km * d
  int proj2d_correct = 0;    // Proj2D <= threshold
  int box_correct = 0;       // projected box IoU >= threshold: counts as a 2D detection
  int outside_envelope = 0;  // targets no template of the archive covers
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
  std::vector<ObjectSummary> objects;         // ascending obj_id
  ObjectSummary overall;                      // every target counted once
  double mean_object_accuracy_percent = 0.0;  // the paper's "average" row: mean over objects
  int frames = 0;
  double mean_frame_ms = 0.0;
  double median_frame_ms = 0.0;
  double p90_frame_ms = 0.0;
};

// The `fraction` quantile (0..1) with linear interpolation between ranks; 0 for no values.
double Quantile(std::vector<double> values, double fraction);

MethodSummary Summarize(const MethodRun& run, const std::map<std::int32_t, EvalModel>& models);

}  // namespace layermod
