// SPDX-License-Identifier: MIT
#include "eval/bench.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "eval/evaluation.h"
#include "util/version.h"

namespace layermod {
namespace {

std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

double Ratio(double other, double first) { return first > 0.0 ? other / first : 0.0; }

EvalMethod DetectorModeMethod(const Detector& detector, DetectorOptions options,
                              DetectionMode mode) {
  options.mode = mode;
  return DetectorMethod(detector, options);
}

// The detector in the options' own mode (`layermod bench --mode`), named "<mode> <search>".
EvalMethod SearchMethod(const Detector& detector, const DetectorOptions& options,
                        std::string_view search) {
  EvalMethod method = DetectorMethod(detector, options);
  method.name = std::string(ModeName(options.mode)) + " " + std::string(search);
  return method;
}

DetectorOptions FlatSearch(DetectorOptions options) {
  options.match.search = TemplateSearchMode::kFlat;
  return options;
}

EvalMethod LinemodMethod(const OpenCvLinemod& linemod, std::string name) {
  return {std::move(name), [&linemod](const BopFrame& frame) {
            return linemod.Detect(frame.color, frame.depth_mm);
          }};
}

nlohmann::json MethodJson(const MethodSummary& method) {
  return {{"method", method.name},
          {"frames", method.frames},
          {"targets", method.overall.frames},
          {"median_ms", method.median_frame_ms},
          {"p90_ms", method.p90_frame_ms},
          {"mean_ms", method.mean_frame_ms},
          {"recall_percent", method.overall.AccuracyPercent()},
          {"proj2d_percent", method.overall.Proj2DPercent()},
          {"detection_rate_percent", method.overall.DetectionRatePercent()},
          {"per_object", ObjectSummariesJson(method)}};
}

nlohmann::json RatiosJson(const std::vector<MethodSummary>& methods) {
  nlohmann::json ratios = nlohmann::json::array();
  if (methods.empty()) return ratios;
  const MethodSummary& first = methods.front();
  for (std::size_t i = 1; i < methods.size(); ++i) {
    const MethodSummary& other = methods[i];
    ratios.push_back({{"method", other.name},
                      {"relative_to", first.name},
                      {"median_time_ratio", Ratio(other.median_frame_ms, first.median_frame_ms)},
                      {"p90_time_ratio", Ratio(other.p90_frame_ms, first.p90_frame_ms)},
                      {"recall_difference_points",
                       other.overall.AccuracyPercent() - first.overall.AccuracyPercent()}});
  }
  return ratios;
}

}  // namespace

std::string_view SuiteName(BenchSuite suite) {
  switch (suite) {
    case BenchSuite::kDepth:
      return "depth";
    case BenchSuite::kColorOnly:
      return "color-only";
    case BenchSuite::kTreeVsFlat:
      return "tree-vs-flat";
  }
  return "depth";
}

BenchResult RunBench(const Detector& detector, BenchSuite suite,
                     const DetectorOptions& detector_options,
                     const std::filesystem::path& dataset_dir,
                     const FrameSelectionOptions& selection, const EvalMetricOptions& metrics,
                     const JobControl& job) {
  detector_options.Validate();
  metrics.Validate();
  const bool with_depth = suite != BenchSuite::kColorOnly;
  const EvalPlan plan =
      PlanEvaluation(dataset_dir, DetectorObjectIds(detector), selection, with_depth);
  BenchResult result;
  result.suite = suite;
  for (const TemplateArchive* archive : detector.archives()) {
    result.templates += archive->templates().size();
  }
  std::vector<EvalMethod> methods;
  std::unique_ptr<OpenCvLinemod> linemod;  // outlives the methods that call it
  if (suite == BenchSuite::kTreeVsFlat) {
    methods = {SearchMethod(detector, detector_options, "tree"),
               SearchMethod(detector, FlatSearch(detector_options), "flat")};
  } else {
    OpenCvLinemodOptions linemod_options;
    linemod_options.threshold_percent = detector_options.match.threshold_percent;
    linemod_options.use_depth = with_depth;
    linemod = std::make_unique<OpenCvLinemod>(detector.archives(), linemod_options, job);
    result.linemod_training = linemod->training();
    if (with_depth) {
      methods = {DetectorModeMethod(detector, detector_options, DetectionMode::kScenePatch),
                 DetectorModeMethod(detector, detector_options, DetectionMode::kExhaustive),
                 LinemodMethod(*linemod, "cv::linemod")};
    } else {
      methods = {DetectorModeMethod(detector, detector_options, DetectionMode::kColorOnly),
                 LinemodMethod(*linemod, "cv::linemod LINE-2D")};
    }
  }
  const EnvelopeMisses misses = FindEnvelopeMisses(detector, plan);
  for (MethodRun& run : RunMethods(plan.dataset, plan.frames, methods, metrics, job)) {
    MarkEnvelopeMisses(misses, run);
    result.methods.push_back(Summarize(run, plan.dataset.models));
  }
  return result;
}

nlohmann::json BenchReportJson(const EvalRunInfo& info, const BenchResult& result) {
  nlohmann::json methods = nlohmann::json::array();
  for (const MethodSummary& method : result.methods) methods.push_back(MethodJson(method));
  nlohmann::json setup = RunInfoJson(info);
  setup.erase("mode");
  setup["suite"] = std::string(SuiteName(result.suite));
  return {{"tool_version", ToolVersion()},
          {"created_utc", UtcTimestamp()},
          {"setup", setup},
          {"templates", result.templates},
          {"linemod_training",
           {{"templates", result.linemod_training.templates},
            {"refused", result.linemod_training.refused},
            {"seconds", result.linemod_training.seconds}}},
          {"methods", methods},
          {"ratios", RatiosJson(result.methods)}};
}

std::string BenchTable(const BenchResult& result) {
  std::string table =
      "| Method | Frames | Median (ms) | p90 (ms) | Mean (ms) | Recall ADD(-S) (%) | "
      "Detection (%) | Median time vs first |\n|---|---:|---:|---:|---:|---:|---:|---:|\n";
  const double first_median = result.methods.empty() ? 0.0 : result.methods.front().median_frame_ms;
  for (const MethodSummary& method : result.methods) {
    table += "| " + method.name + " | " + std::to_string(method.frames) + " | " +
             Fixed(method.median_frame_ms, 1) + " | " + Fixed(method.p90_frame_ms, 1) + " | " +
             Fixed(method.mean_frame_ms, 1) + " | " + Fixed(method.overall.AccuracyPercent(), 1) +
             " | " + Fixed(method.overall.DetectionRatePercent(), 1) + " | " +
             Fixed(Ratio(method.median_frame_ms, first_median), 2) + "x |\n";
  }
  return table;
}

}  // namespace layermod
