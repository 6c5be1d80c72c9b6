// SPDX-License-Identifier: MIT
#pragma once

// report.json and report.md of `layermod eval`, and the table it prints.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/eval_runner.h"
#include "eval/eval_summary.h"
#include "pipeline/detector.h"

namespace layermod {

// How the run was set up, recorded so a report says what it measured.
struct EvalRunInfo {
  std::string dataset_dir;
  std::vector<std::string> archives;
  std::string targets_file;  // empty: every annotated instance of the archives' objects
  std::optional<int> scene_id;
  double min_visib_fract = 0.5;
  int max_frames = 0;
  DetectorOptions detector;  // every detector setting of the run (bench varies the mode)
  EvalMetricOptions metrics;
};

// UTC now as ISO 8601 ("2026-11-22T07:00:00Z").
std::string UtcTimestamp();

nlohmann::json RunInfoJson(const EvalRunInfo& info);
nlohmann::json ObjectSummariesJson(const MethodSummary& summary);  // one entry per object
// With the precision-recall curve over every threshold.
nlohmann::json SummaryJson(const MethodSummary& summary);
nlohmann::json OutcomesJson(const MethodRun& run);

// {tool_version, created_utc, setup, summary, outcomes}.
nlohmann::json EvalReportJson(const EvalRunInfo& info, const MethodSummary& summary,
                              const MethodRun& run);

// A Markdown table, one row per object plus "all" (the paper's Table 4 with more columns).
std::string SummaryTable(const MethodSummary& summary);
std::string EvalReportMarkdown(const EvalRunInfo& info, const MethodSummary& summary,
                               const MethodRun& run);

// One line per object with targets outside the archive's envelope ("" when none): such misses
// are a training question, not a detection failure.
std::string EnvelopeCoverageText(const MethodSummary& summary, const MethodRun& run);

// Throws IoError unless `out_dir` is a writable folder or can be created as one (its parent is a
// writable folder): lets a run fail before the work rather than after it.
void CheckReportFolder(const std::filesystem::path& out_dir);

// Precision and recall at the run's threshold, false detections of absent objects, the area
// under the precision-recall curve.
std::string ConfidenceText(const MethodSummary& summary);

// "Targets missed: N of M: a outside the envelope, b not detected, c with a wrong pose (d of them
// accepted), e with a right pose below the confidence threshold.", empty when none was missed;
// and the same per object as a markdown table.
std::string MissesText(const MethodSummary& summary);
std::string MissesTable(const MethodSummary& summary);

// Creates `out_dir` if needed and writes report.json, report.md and pr_curve.png atomically. Throws
// IoError.
void WriteEvalReport(const std::filesystem::path& out_dir, const EvalRunInfo& info,
                     const MethodSummary& summary, const MethodRun& run);

}  // namespace layermod
