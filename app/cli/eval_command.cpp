// SPDX-License-Identifier: MIT
#include "cli/eval_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "eval/bop_targets.h"
#include "eval/eval_report.h"
#include "eval/evaluation.h"
#include "pipeline/detector.h"

namespace layermod::cli {
namespace {

namespace fs = std::filesystem;

struct EvalArgs {
  std::vector<std::string> archives;
  std::string dataset;
  int scene_id = -1;
  std::string targets;
  std::string mode = "scene-patch";
  double min_visib = 0.5;
  double km = 0.1;
  int frames = 0;
  std::string out;
};

FrameSelectionOptions BuildSelection(const EvalArgs& args) {
  FrameSelectionOptions selection;
  if (args.scene_id >= 0) selection.scene_id = args.scene_id;
  if (!args.targets.empty()) selection.targets = LoadBopTargets(args.targets);
  selection.min_visib_fract = args.min_visib;
  selection.max_frames = args.frames;
  selection.Validate();
  return selection;
}

EvalRunInfo BuildRunInfo(const EvalArgs& args, const FrameSelectionOptions& selection,
                         const EvalMetricOptions& metrics) {
  EvalRunInfo info;
  info.dataset_dir = args.dataset;
  info.archives = args.archives;
  info.mode = args.mode;
  info.targets_file = args.targets;
  info.scene_id = selection.scene_id;
  info.min_visib_fract = selection.min_visib_fract;
  info.max_frames = selection.max_frames;
  info.metrics = metrics;
  return info;
}

Evaluation EvaluateWithProgress(const Detector& detector, const DetectorOptions& options,
                                const EvalArgs& args, const FrameSelectionOptions& selection,
                                const EvalMetricOptions& metrics) {
  CancelToken cancel;
  InterruptScope interrupt(cancel);
  ProgressBar bar;
  const JobControl job([&bar](std::size_t done, std::size_t total,
                              std::string_view stage) { bar.Update(done, total, stage); },
                       &cancel);
  try {
    Evaluation evaluation = Evaluate(detector, options, args.dataset, selection, metrics, job);
    bar.Finish();
    return evaluation;
  } catch (...) {
    bar.Finish();
    throw;
  }
}

void RunEval(const EvalArgs& args) {
  DetectorOptions options;
  options.mode = ParseDetectionMode(args.mode);
  options.Validate();
  EvalMetricOptions metrics;
  metrics.km = args.km;
  metrics.Validate();
  const FrameSelectionOptions selection = BuildSelection(args);
  CheckReportFolder(args.out);
  std::vector<TemplateArchive> archives;
  for (const std::string& path : args.archives) archives.push_back(ReadArchive(path));
  const Detector detector(std::move(archives));
  const Evaluation evaluation = EvaluateWithProgress(detector, options, args, selection, metrics);
  const EvalRunInfo info = BuildRunInfo(args, selection, metrics);
  WriteEvalReport(args.out, info, evaluation.summary, evaluation.run);
  std::printf("%s", SummaryTable(evaluation.summary).c_str());
  std::printf("mean accuracy over objects %.1f %%; time per frame median %.1f ms, p90 %.1f ms\n",
              evaluation.summary.mean_object_accuracy_percent, evaluation.summary.median_frame_ms,
              evaluation.summary.p90_frame_ms);
  std::printf("report        %s\n", (fs::path(args.out) / "report.md").string().c_str());
}

}  // namespace

void AddEvalCommand(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = app.add_subcommand(
      "eval", "Measure detection accuracy (ADD/ADD-S, Proj2D) and time on a BOP dataset");
  command->add_option("--archive", args->archives, "Template archive(s) (*.layermod)")->required();
  command->add_option("--dataset", args->dataset, "BOP dataset root or split folder (test/)")
      ->required();
  command->add_option("--scene", args->scene_id, "Only this scene id");
  command->add_option("--targets", args->targets,
                      "BOP targets file (test_targets_bop19.json): only the listed objects");
  command->add_option("--mode", args->mode, "scene-patch, exhaustive or color-only")
      ->check(CLI::IsMember({"scene-patch", "exhaustive", "color-only"}))
      ->capture_default_str();
  command->add_option("--min-visib", args->min_visib, "Skip instances less visible than this")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--km", args->km, "Correct when ADD(-S) <= km x diameter")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--frames", args->frames, "Evaluate at most this many frames (0 = all)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_option("--out", args->out, "Folder for report.json and report.md")->required();
  command->callback([args] { RunEval(*args); });
}

}  // namespace layermod::cli
