// SPDX-License-Identifier: MIT
#include "eval/eval_summary.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace layermod {
namespace {

double Mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

// The cause of a target's miss (ObjectSummary), nothing for a correct accepted detection.
void CountMiss(const TargetOutcome& outcome, double min_confidence, ObjectSummary& summary) {
  const bool accepted = Accepted(outcome, min_confidence);
  if (accepted && outcome.pose.correct) return;
  if (outcome.outside_envelope) {
    ++summary.missed_outside_envelope;
  } else if (!outcome.detected) {
    ++summary.missed_undetected;
  } else if (!outcome.pose.correct) {
    ++summary.missed_wrong_pose;
    summary.wrong_pose_accepted += accepted ? 1 : 0;
  } else {
    ++summary.missed_below_threshold;
  }
}

ObjectSummary SummarizeOutcomes(const std::vector<const TargetOutcome*>& outcomes,
                                double min_confidence) {
  ObjectSummary summary;
  std::vector<double> times_ms;
  for (const TargetOutcome* outcome : outcomes) {
    if (!outcome->present) {
      ++summary.absent;
      summary.absent_detected += Accepted(*outcome, min_confidence) ? 1 : 0;
      continue;
    }
    ++summary.frames;
    times_ms.push_back(outcome->frame_time_ms);
    summary.outside_envelope += outcome->outside_envelope ? 1 : 0;
    CountMiss(*outcome, min_confidence, summary);
    if (!Accepted(*outcome, min_confidence)) continue;
    ++summary.detected;
    summary.correct += outcome->pose.correct ? 1 : 0;
    summary.proj2d_correct += outcome->pose.proj2d_correct ? 1 : 0;
    summary.box_correct += outcome->pose.box_correct ? 1 : 0;
  }
  summary.mean_time_ms = Mean(times_ms);
  summary.median_time_ms = Quantile(times_ms, 0.5);
  return summary;
}

}  // namespace

double Quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (rank - static_cast<double>(below)) * (values[above] - values[below]);
}

bool Accepted(const TargetOutcome& outcome, double min_confidence) {
  return outcome.detected && outcome.confidence >= min_confidence;
}

MethodSummary Summarize(const MethodRun& run, const std::map<std::int32_t, EvalModel>& models,
                        double min_confidence) {
  MethodSummary summary;
  summary.name = run.name;
  summary.min_confidence = min_confidence;
  std::map<std::int32_t, std::vector<const TargetOutcome*>> by_object;
  std::vector<const TargetOutcome*> all;
  for (const TargetOutcome& outcome : run.outcomes) {
    by_object[outcome.obj_id].push_back(&outcome);
    all.push_back(&outcome);
  }
  double accuracy_sum = 0.0;
  int objects_with_targets = 0;
  for (const auto& [obj_id, outcomes] : by_object) {
    ObjectSummary object = SummarizeOutcomes(outcomes, min_confidence);
    object.obj_id = obj_id;
    if (const auto model = models.find(obj_id); model != models.end()) {
      object.symmetric_metric = model->second.symmetric;
      object.diameter_mm = model->second.diameter_mm;
    }
    if (object.frames > 0) {  // an object only ever absent has no accuracy
      accuracy_sum += object.AccuracyPercent();
      ++objects_with_targets;
    }
    summary.objects.push_back(object);
  }
  summary.overall = SummarizeOutcomes(all, min_confidence);
  if (objects_with_targets > 0) {
    summary.mean_object_accuracy_percent = accuracy_sum / objects_with_targets;
  }
  summary.precision_recall = ComputePrecisionRecall(run.outcomes);
  summary.frames = static_cast<int>(run.frame_times_ms.size());
  summary.mean_frame_ms = Mean(run.frame_times_ms);
  summary.median_frame_ms = Quantile(run.frame_times_ms, 0.5);
  summary.p90_frame_ms = Quantile(run.frame_times_ms, 0.9);
  return summary;
}

}  // namespace layermod
