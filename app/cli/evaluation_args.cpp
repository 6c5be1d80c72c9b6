// SPDX-License-Identifier: MIT
#include "cli/evaluation_args.h"

#include "eval/bop_targets.h"
#include "templates/archive.h"

namespace layermod::cli {

void AddEvaluationOptions(CLI::App* command, EvaluationArgs& args) {
  command->add_option("--archive", args.archives, "Template archive(s) (*.layermod)")->required();
  command->add_option("--dataset", args.dataset, "BOP dataset root or split folder (test/)")
      ->required();
  command->add_option("--scene", args.scene_id, "Only this scene id");
  command->add_option("--targets", args.targets,
                      "BOP targets file (test_targets_bop19.json): only the listed objects");
  command->add_option("--min-visib", args.min_visib, "Skip instances less visible than this")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command->add_option("--km", args.km, "Correct when ADD(-S) <= km x diameter")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--frames", args.frames, "At most this many frames (0 = all)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  command->add_flag("--no-absent", args.no_absent,
                    "Judge only the objects a frame shows (by default a detection of an object "
                    "the frame does not show counts as a false one)");
  args.detector.AddTo(command);
}

FrameSelectionOptions BuildSelection(const EvaluationArgs& args) {
  FrameSelectionOptions selection;
  if (args.scene_id >= 0) selection.scene_id = args.scene_id;
  if (!args.targets.empty()) selection.targets = LoadBopTargets(args.targets);
  selection.min_visib_fract = args.min_visib;
  selection.max_frames = args.frames;
  selection.absent_objects = !args.no_absent;
  selection.Validate();
  return selection;
}

EvalMetricOptions BuildMetrics(const EvaluationArgs& args) {
  EvalMetricOptions metrics;
  metrics.km = args.km;
  metrics.Validate();
  return metrics;
}

EvalRunInfo BuildRunInfo(const EvaluationArgs& args, const FrameSelectionOptions& selection,
                         const EvalMetricOptions& metrics) {
  EvalRunInfo info;
  info.dataset_dir = args.dataset;
  info.archives = args.archives;
  info.targets_file = args.targets;
  info.scene_id = selection.scene_id;
  info.min_visib_fract = selection.min_visib_fract;
  info.max_frames = selection.max_frames;
  info.detector = args.detector.Resolve();
  info.metrics = metrics;
  return info;
}

Detector LoadDetector(const EvaluationArgs& args) {
  std::vector<TemplateArchive> archives;
  for (const std::string& path : args.archives) archives.push_back(ReadArchive(path));
  return Detector(std::move(archives));
}

}  // namespace layermod::cli
