// SPDX-License-Identifier: MIT
#include "cli/eval_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/evaluation_args.h"
#include "cli/progress_job.h"
#include "eval/bop_targets.h"
#include "eval/eval_report.h"
#include "eval/evaluation.h"
#include "pipeline/detector.h"

namespace layermod::cli {
namespace {

namespace fs = std::filesystem;

struct EvalArgs : EvaluationArgs {
  std::string out;
};

void RunEval(const EvalArgs& args) {
  const DetectorOptions options = args.detector.Resolve();
  const EvalMetricOptions metrics = BuildMetrics(args);
  const FrameSelectionOptions selection = BuildSelection(args);
  CheckReportFolder(args.out);
  const Detector detector = LoadDetector(args);
  const Evaluation evaluation = RunWithProgress([&](const JobControl& job) {
    return Evaluate(detector, options, args.dataset, selection, metrics, job);
  });
  EvalRunInfo info = BuildRunInfo(args, selection, metrics);
  WriteEvalReport(args.out, info, evaluation.summary, evaluation.run);
  std::printf("%s", SummaryTable(evaluation.summary).c_str());
  std::printf("mean accuracy over objects %.1f %%; time per frame median %.1f ms, p90 %.1f ms\n",
              evaluation.summary.mean_object_accuracy_percent, evaluation.summary.median_frame_ms,
              evaluation.summary.p90_frame_ms);
  std::printf("%s", ConfidenceText(evaluation.summary).c_str());
  std::printf("%s", MissesText(evaluation.summary).c_str());
  std::printf("%s", EnvelopeCoverageText(evaluation.summary, evaluation.run).c_str());
  std::printf("report        %s\n", (fs::path(args.out) / "report.md").string().c_str());
}

}  // namespace

void AddEvalCommand(CLI::App& app) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = app.add_subcommand(
      "eval", "Measure detection accuracy (ADD/ADD-S, Proj2D) and time on a BOP dataset");
  AddEvaluationOptions(command, *args);
  command->add_option("--out", args->out, "Folder for report.json and report.md")->required();
  command->callback([args] { RunEval(*args); });
}

}  // namespace layermod::cli
