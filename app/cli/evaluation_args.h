// SPDX-License-Identifier: MIT
// What `layermod eval` and `layermod bench` share: the archives, the dataset and which frames.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cli/detector_flags.h"
#include "eval/eval_frames.h"
#include "eval/eval_report.h"
#include "eval/pose_scoring.h"
#include "pipeline/detector.h"

namespace layermod::cli {

struct EvaluationArgs {
  std::vector<std::string> archives;
  std::string dataset;
  int scene_id = -1;
  std::string targets;
  double min_visib = 0.5;
  double km = 0.1;
  int frames = 0;
  bool no_absent = false;
  DetectorFlags detector;
};

// --archive --dataset --scene --targets --min-visib --km --frames --no-absent and the detector's
// flags.
void AddEvaluationOptions(CLI::App* command, EvaluationArgs& args);

FrameSelectionOptions BuildSelection(const EvaluationArgs& args);
EvalMetricOptions BuildMetrics(const EvaluationArgs& args);
EvalRunInfo BuildRunInfo(const EvaluationArgs& args, const FrameSelectionOptions& selection,
                         const EvalMetricOptions& metrics);
Detector LoadDetector(const EvaluationArgs& args);

}  // namespace layermod::cli
