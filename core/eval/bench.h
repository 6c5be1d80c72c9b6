// SPDX-License-Identifier: MIT
#pragma once

// `layermod bench`: Scene-Patch, exhaustive matching and OpenCV's cv::linemod on the same
// frames with the same templates, side by side in one run (SPEC §5).

#include <cstddef>
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "eval/eval_frames.h"
#include "eval/eval_report.h"
#include "eval/eval_summary.h"
#include "eval/opencv_linemod.h"
#include "pipeline/detector.h"

namespace layermod {

struct BenchResult {
  std::size_t templates = 0;  // in the archives
  OpenCvLinemodTraining linemod_training;
  std::vector<MethodSummary> methods;  // scene-patch, exhaustive, cv::linemod
};

// `detector_options` sets everything but the mode (scene-patch, then exhaustive); cv::linemod
// uses its match threshold. The dataset must have depth. Throws like PlanEvaluation, Cancelled.
BenchResult RunBench(const Detector& detector, const DetectorOptions& detector_options,
                     const std::filesystem::path& dataset_dir,
                     const FrameSelectionOptions& selection, const EvalMetricOptions& metrics,
                     const JobControl& job = {});

// {tool_version, created_utc, setup, templates, linemod_training, methods: [...], ratios}. The
// ratios compare each method with the first: median and p90 time per frame (other / first) and
// recall (ADD(-S) at km * d) in percentage points (other - first).
nlohmann::json BenchReportJson(const EvalRunInfo& info, const BenchResult& result);

// A Markdown table, one row per method.
std::string BenchTable(const BenchResult& result);

}  // namespace layermod
