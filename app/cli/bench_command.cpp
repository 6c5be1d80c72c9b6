// SPDX-License-Identifier: MIT
#include "cli/bench_command.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/evaluation_args.h"
#include "cli/progress_job.h"
#include "eval/bench.h"
#include "eval/bop_targets.h"
#include "pipeline/detector.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod::cli {
namespace {

struct BenchArgs : EvaluationArgs {
  bool color_only = false;
  bool tree_vs_flat = false;
  std::string out;
};

// Timings of an unoptimised build would mislead whoever reads the JSON.
void RequireReleaseBuild() {
#ifndef NDEBUG
  throw Error("bench measures speed: build layermod with CMAKE_BUILD_TYPE=Release");
#endif
}

void RunBenchCommand(const BenchArgs& args) {
  RequireReleaseBuild();
  const DetectorOptions options = args.detector.Resolve();
  const EvalMetricOptions metrics = BuildMetrics(args);
  const FrameSelectionOptions selection = BuildSelection(args);
  CheckWritableTarget(args.out);
  const Detector detector = LoadDetector(args);
  if (args.color_only && args.tree_vs_flat) {
    throw CLI::ValidationError("--color-only and --tree-vs-flat: choose one");
  }
  const BenchSuite suite = args.color_only     ? BenchSuite::kColorOnly
                           : args.tree_vs_flat ? BenchSuite::kTreeVsFlat
                                               : BenchSuite::kDepth;
  const BenchResult result = RunWithProgress([&](const JobControl& job) {
    return RunBench(detector, suite, options, args.dataset, selection, metrics, job);
  });
  WriteFileAtomically(
      args.out, BenchReportJson(BuildRunInfo(args, selection, metrics), result).dump(2) + "\n");
  std::printf("%s", BenchTable(result).c_str());
  if (suite == BenchSuite::kTreeVsFlat) {
    std::printf("templates     %zu\n", result.templates);
  } else {
    std::printf("templates     %zu (cv::linemod took %d, refused %d, in %.1f s)\n",
                result.templates, result.linemod_training.templates,
                result.linemod_training.refused, result.linemod_training.seconds);
  }
  std::printf("report        %s\n", args.out.c_str());
}

}  // namespace

void AddBenchCommand(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* command = app.add_subcommand(
      "bench", "Time Scene-Patch, exhaustive matching and cv::linemod on the same frames");
  AddEvaluationOptions(command, *args);
  command->add_flag("--color-only", args->color_only,
                    "RGB datasets: LINE-2D (color-only mode) vs cv::linemod LINE-2D");
  command->add_flag("--tree-vs-flat", args->tree_vs_flat,
                    "Large archives: the view tree (--tree-descend) vs the flat search, in the "
                    "--mode asked for (default scene-patch), no cv::linemod");
  command->add_option("--out", args->out, "bench.json to write")->required();
  command->callback([args] { RunBenchCommand(*args); });
}

}  // namespace layermod::cli
