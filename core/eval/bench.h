// SPDX-License-Identifier: MIT
#pragma once

// `layermod bench`: Scene-Patch, exhaustive matching and OpenCV's cv::linemod on the same
// frames with the same templates, side by side in one run (paper §4.3; docs/RESULTS.md).

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

// Which methods run side by side.
enum class BenchSuite {
  kDepth,       // scene-patch, exhaustive, cv::linemod (colour gradients + depth normals)
  kColorOnly,   // color-only (LINE-2D), cv::linemod LINE-2D: for RGB datasets
  kTreeVsFlat,  // scene-patch with the view tree, scene-patch flat: for large archives
};

struct BenchResult {
  BenchSuite suite = BenchSuite::kDepth;
  std::size_t templates = 0;               // in the archives
  OpenCvLinemodTraining linemod_training;  // none for kTreeVsFlat
  std::vector<MethodSummary> methods;      // in BenchSuite order
};

// `detector_options` sets everything but the mode; cv::linemod uses its match threshold. With
// BenchSuite::kDepth the dataset must have depth. Throws like PlanEvaluation, and Cancelled.
BenchResult RunBench(const Detector& detector, BenchSuite suite,
                     const DetectorOptions& detector_options,
                     const std::filesystem::path& dataset_dir,
                     const FrameSelectionOptions& selection, const EvalMetricOptions& metrics,
                     const JobControl& job = {});

// "depth", "color-only" or "tree-vs-flat".
std::string_view SuiteName(BenchSuite suite);

// {tool_version, created_utc, setup (with the suite), templates, linemod_training, methods: [...],
// ratios}. The ratios compare each method with the first: median and p90 time per frame (other /
// first) and recall (ADD(-S) at km * d) in percentage points (other - first).
nlohmann::json BenchReportJson(const EvalRunInfo& info, const BenchResult& result);

// A Markdown table, one row per method.
std::string BenchTable(const BenchResult& result);

}  // namespace layermod
