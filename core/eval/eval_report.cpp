// SPDX-License-Identifier: MIT
#include "eval/eval_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <nlohmann/json.hpp>

#include "dataset/bop_images.h"
#include "eval/precision_recall.h"
#include "pipeline/detector_options.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"
#include "util/version.h"

namespace layermod {
namespace {

// JSON has no infinity: an unusable 2D error is written as null.
nlohmann::json FiniteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

nlohmann::json ObjectJson(const ObjectSummary& object) {
  return {{"obj_id", object.obj_id},
          {"metric", object.symmetric_metric ? "ADD-S" : "ADD"},
          {"diameter_mm", object.diameter_mm},
          {"frames", object.frames},
          {"detected", object.detected},
          {"correct", object.correct},
          {"proj2d_correct", object.proj2d_correct},
          {"box_correct", object.box_correct},
          {"outside_envelope", object.outside_envelope},
          {"absent", object.absent},
          {"absent_detected", object.absent_detected},
          {"misses",
           {{"outside_envelope", object.missed_outside_envelope},
            {"undetected", object.missed_undetected},
            {"wrong_pose", object.missed_wrong_pose},
            {"wrong_pose_accepted", object.wrong_pose_accepted},
            {"right_below_threshold", object.missed_below_threshold}}},
          {"accuracy_percent", object.AccuracyPercent()},
          {"precision_percent", object.PrecisionPercent()},
          {"absent_detected_percent", object.AbsentDetectedPercent()},
          {"proj2d_percent", object.Proj2DPercent()},
          {"detection_rate_percent", object.DetectionRatePercent()},
          {"mean_time_ms", object.mean_time_ms},
          {"median_time_ms", object.median_time_ms}};
}

std::string TableRow(const std::string& label, const std::string& metric,
                     const ObjectSummary& row) {
  return "| " + label + " | " + metric + " | " + std::to_string(row.frames) + " | " +
         Fixed(row.AccuracyPercent(), 1) + " | " + Fixed(row.Proj2DPercent(), 1) + " | " +
         Fixed(row.DetectionRatePercent(), 1) + " | " + Fixed(row.mean_time_ms, 1) + " | " +
         Fixed(row.median_time_ms, 1) + " |\n";
}

}  // namespace

std::string UtcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

nlohmann::json RunInfoJson(const EvalRunInfo& info) {
  return {{"dataset", info.dataset_dir},
          {"archives", info.archives},
          {"mode", std::string(ModeName(info.detector.mode))},
          {"targets_file", info.targets_file},
          {"scene_id", info.scene_id ? nlohmann::json(*info.scene_id) : nlohmann::json(nullptr)},
          {"min_visib_fract", info.min_visib_fract},
          {"max_frames", info.max_frames},
          {"detector", DetectorOptionsToJson(info.detector)},
          {"km", info.metrics.km},
          {"proj2d_threshold_px", info.metrics.proj2d_threshold_px},
          {"min_box_iou", info.metrics.min_box_iou}};
}

nlohmann::json ObjectSummariesJson(const MethodSummary& summary) {
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectSummary& object : summary.objects) objects.push_back(ObjectJson(object));
  return objects;
}

nlohmann::json SummaryJson(const MethodSummary& summary) {
  const nlohmann::json objects = ObjectSummariesJson(summary);
  nlohmann::json overall = ObjectJson(summary.overall);
  overall.erase("obj_id");
  overall.erase("metric");
  overall.erase("diameter_mm");
  const PrecisionRecallCurve& curve = summary.precision_recall;
  nlohmann::json points = nlohmann::json::array();
  for (const PrecisionRecallPoint& point : curve.points) {
    points.push_back({point.threshold, point.precision, point.recall});
  }
  return {{"method", summary.name},
          {"min_confidence", summary.min_confidence},
          {"frames", summary.frames},
          {"objects", objects},
          {"overall", overall},
          {"mean_object_accuracy_percent", summary.mean_object_accuracy_percent},
          {"frame_time_ms",
           {{"mean", summary.mean_frame_ms},
            {"median", summary.median_frame_ms},
            {"p90", summary.p90_frame_ms}}},
          {"precision_recall",
           {{"area", curve.area},
            {"targets", curve.targets},
            {"points", points},
            {"point_fields", {"threshold", "precision", "recall"}}}}};
}

nlohmann::json OutcomesJson(const MethodRun& run) {
  nlohmann::json outcomes = nlohmann::json::array();
  for (const TargetOutcome& outcome : run.outcomes) {
    nlohmann::json entry = {{"scene_id", outcome.scene_id}, {"im_id", outcome.image_id},
                            {"obj_id", outcome.obj_id},     {"present", outcome.present},
                            {"detected", outcome.detected}, {"time_ms", outcome.frame_time_ms}};
    if (outcome.outside_envelope) entry["outside_envelope"] = outcome.envelope_note;
    if (outcome.detected) {
      entry["score"] = outcome.score;
      entry["confidence"] = outcome.confidence;
      nlohmann::json features = nlohmann::json::object();
      const auto names = ConfidenceFeatures::Names();
      for (std::size_t i = 0; i < names.size(); ++i) {
        features[std::string(names[i])] = outcome.features.values[i];
      }
      entry["features"] = features;
    }
    if (outcome.detected && outcome.present) {
      entry["error_mm"] = FiniteOrNull(outcome.pose.error_mm);
      entry["proj2d_px"] = FiniteOrNull(outcome.pose.proj2d_px);
      entry["box_iou"] = outcome.pose.box_iou;
      entry["correct"] = outcome.pose.correct;
      entry["proj2d_correct"] = outcome.pose.proj2d_correct;
      entry["box_correct"] = outcome.pose.box_correct;
    }
    outcomes.push_back(entry);
  }
  return outcomes;
}

nlohmann::json EvalReportJson(const EvalRunInfo& info, const MethodSummary& summary,
                              const MethodRun& run) {
  return {{"tool_version", ToolVersion()},
          {"created_utc", UtcTimestamp()},
          {"setup", RunInfoJson(info)},
          {"summary", SummaryJson(summary)},
          {"outcomes", OutcomesJson(run)}};
}

std::string SummaryTable(const MethodSummary& summary) {
  std::string table =
      "| Object | Metric | Frames | Accuracy (%) | Proj2D (%) | Detection (%) | Mean time (ms) | "
      "Median time (ms) |\n|---|---|---:|---:|---:|---:|---:|---:|\n";
  for (const ObjectSummary& object : summary.objects) {
    table +=
        TableRow(std::to_string(object.obj_id), object.symmetric_metric ? "ADD-S" : "ADD", object);
  }
  table += TableRow("all", "", summary.overall);
  return table;
}

std::string EnvelopeCoverageText(const MethodSummary& summary, const MethodRun& run) {
  std::string text;
  for (const ObjectSummary& object : summary.objects) {
    if (object.outside_envelope == 0) continue;
    const auto first = std::find_if(run.outcomes.begin(), run.outcomes.end(), [&](const auto& o) {
      return o.obj_id == object.obj_id && o.outside_envelope;
    });
    // More than a sampling step from every template: none matches them closely, though ICP can
    // still turn a near template's pose onto some of them.
    const int found = object.outside_envelope - object.missed_outside_envelope;
    text += "obj " + std::to_string(object.obj_id) + ": " +
            std::to_string(object.outside_envelope) + " of " + std::to_string(object.frames) +
            " targets outside the archive's envelope, farther than a sampling step from every "
            "template, " +
            std::to_string(found) + " of them found all the same (first: scene " +
            std::to_string(first->scene_id) + " image " + std::to_string(first->image_id) + ", " +
            first->envelope_note + ")\n";
  }
  return text;
}

std::string MissesText(const MethodSummary& summary) {
  const ObjectSummary& all = summary.overall;
  const int missed = all.frames - all.correct;
  if (missed <= 0) return "";
  return "Targets missed: " + std::to_string(missed) + " of " + std::to_string(all.frames) + ": " +
         std::to_string(all.missed_outside_envelope) + " outside the envelope, " +
         std::to_string(all.missed_undetected) + " not detected, " +
         std::to_string(all.missed_wrong_pose) + " with a wrong pose (" +
         std::to_string(all.wrong_pose_accepted) + " of them accepted), " +
         std::to_string(all.missed_below_threshold) +
         " with a right pose below the confidence threshold.\n";
}

std::string MissesTable(const MethodSummary& summary) {
  std::string table =
      "| Object | Targets | Right | Outside envelope | Not detected | Wrong pose (accepted) | "
      "Right, below threshold |\n|---|---:|---:|---:|---:|---:|---:|\n";
  const auto row = [&](const std::string& label, const ObjectSummary& object) {
    table += "| " + label + " | " + std::to_string(object.frames) + " | " +
             std::to_string(object.correct) + " | " +
             std::to_string(object.missed_outside_envelope) + " | " +
             std::to_string(object.missed_undetected) + " | " +
             std::to_string(object.missed_wrong_pose) + " (" +
             std::to_string(object.wrong_pose_accepted) + ") | " +
             std::to_string(object.missed_below_threshold) + " |\n";
  };
  for (const ObjectSummary& object : summary.objects) {
    if (object.frames > 0) row(std::to_string(object.obj_id), object);
  }
  row("all", summary.overall);
  return table;
}

std::string ConfidenceText(const MethodSummary& summary) {
  const ObjectSummary& all = summary.overall;
  std::string text = "Detections accepted at confidence >= " + Fixed(summary.min_confidence, 2) +
                     ": precision " + Fixed(all.PrecisionPercent(), 1) + " %, recall " +
                     Fixed(all.AccuracyPercent(), 1) + " %";
  if (all.absent > 0) {
    text += "; objects not in the frame detected in " + std::to_string(all.absent_detected) +
            " of " + std::to_string(all.absent) + " cases (" +
            Fixed(all.AbsentDetectedPercent(), 1) + " %)";
  }
  text += ". Area under the precision-recall curve: " + Fixed(summary.precision_recall.area, 3) +
          " (`pr_curve.png`).\n";
  return text;
}

std::string EvalReportMarkdown(const EvalRunInfo& info, const MethodSummary& summary,
                               const MethodRun& run) {
  std::string archives;
  for (const std::string& archive : info.archives) {
    archives += (archives.empty() ? "" : ", ") + archive;
  }
  std::string text = "# LayerMOD evaluation\n\n";
  text += "- dataset: `" + info.dataset_dir + "`" +
          (info.scene_id ? " (scene " + std::to_string(*info.scene_id) + ")" : "") + "\n";
  text += "- archives: " + archives + "\n";
  text += "- mode: " + std::string(ModeName(info.detector.mode)) + "\n";
  text += "- detector settings: " + DetectorOptionsToJson(info.detector).dump() + "\n";
  if (!info.targets_file.empty()) text += "- targets: `" + info.targets_file + "`\n";
  text += "- correct: ADD (ADD-S for symmetric objects) <= " + Fixed(info.metrics.km, 2) +
          " x diameter; Proj2D <= " + Fixed(info.metrics.proj2d_threshold_px, 1) +
          " px; detection: projected box IoU >= " + Fixed(info.metrics.min_box_iou, 2) + "\n";
  text += "- instances with visibility >= " + Fixed(info.min_visib_fract, 2) + "; " +
          std::to_string(summary.frames) + " frames\n";
  text += "- layermod " + ToolVersion() + ", " + UtcTimestamp() + "\n\n";
  text += SummaryTable(summary);
  text += "\nMean accuracy over objects: " + Fixed(summary.mean_object_accuracy_percent, 1) +
          " %. Time per frame: mean " + Fixed(summary.mean_frame_ms, 1) + " ms, median " +
          Fixed(summary.median_frame_ms, 1) + " ms, p90 " + Fixed(summary.p90_frame_ms, 1) +
          " ms.\n";
  text += "\n" + ConfidenceText(summary);
  if (const std::string misses = MissesText(summary); !misses.empty()) {
    text += "\n" + misses + "\n" + MissesTable(summary);
  }
  const std::string coverage = EnvelopeCoverageText(summary, run);
  if (!coverage.empty()) text += "\n" + coverage;
  return text;
}

void CheckReportFolder(const std::filesystem::path& out_dir) {
  std::error_code ec;
  if (std::filesystem::is_directory(out_dir, ec)) {
    CheckWritableTarget(out_dir / "report.json");
  } else {
    CheckWritableTarget(out_dir);
  }
}

void WriteEvalReport(const std::filesystem::path& out_dir, const EvalRunInfo& info,
                     const MethodSummary& summary, const MethodRun& run) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw IoError(Quoted(out_dir) + ": cannot create the folder (" + ec.message() + ")");
  WriteFileAtomically(out_dir / "report.json", EvalReportJson(info, summary, run).dump(2) + "\n");
  WriteFileAtomically(out_dir / "report.md", EvalReportMarkdown(info, summary, run));
  WritePngAtomically(
      out_dir / "pr_curve.png",
      DrawPrecisionRecall(summary.precision_recall, PointAt(run.outcomes, summary.min_confidence)));
}

}  // namespace layermod
