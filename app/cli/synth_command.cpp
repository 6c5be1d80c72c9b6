// SPDX-License-Identifier: MIT
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/progress_job.h"
#include "geometry/camera.h"
#include "geometry/up_axis.h"
#include "synth/synthesizer.h"
#include "util/error.h"

namespace layermod::cli {
namespace {

namespace fs = std::filesystem;

// The flags bind straight to SynthOptions, so its defaults are the ones --help shows; the
// paths and the up axis are kept as text until the options are built.
struct SynthArgs {
  SynthOptions options;
  std::string models;
  std::string backgrounds;
  std::string camera;
  std::string up_axis = "+z";
  bool no_noise = false;
  std::string out;
};

// --camera, else the BOP dataset's camera.json beside the models folder (or, for a single
// model file, in its folder).
fs::path CameraPath(const SynthArgs& args) {
  if (!args.camera.empty()) return args.camera;
  const fs::path models(args.models);
  std::error_code ec;
  const fs::path beside = fs::is_regular_file(models, ec)
                              ? models.parent_path() / "camera.json"
                              : (models / ".." / "camera.json").lexically_normal();
  if (fs::is_regular_file(beside, ec)) return beside;
  throw Error("no --camera given and '" + beside.string() +
              "' does not exist; give the sensor's camera.json");
}

SynthOptions BuildOptions(const SynthArgs& args) {
  SynthOptions options = args.options;
  options.models_dir = args.models;
  options.backgrounds_dir = args.backgrounds;
  options.upright_from_model = UprightFromUpAxis(args.up_axis);
  options.noise.enabled = !args.no_noise;
  options.out_dir = args.out;
  options.camera = LoadCameraJson(CameraPath(args));
  options.Validate();
  return options;
}

void PrintSummary(const SynthSummary& summary) {
  std::string per_target;
  for (const auto& [obj_id, images] : summary.images_per_target) {
    if (!per_target.empty()) per_target += ", ";
    per_target += "obj " + std::to_string(obj_id) + ": " + std::to_string(images);
  }
  std::printf("images        %d (%s)\n", summary.images, per_target.c_str());
  std::printf("distance      %.0f..%.0f mm (camera to target sphere centre)\n",
              summary.min_distance_mm, summary.max_distance_mm);
  std::printf("visibility    min %.2f, mean %.2f (target)\n", summary.min_visibility,
              summary.mean_visibility);
  if (summary.images_without_target > 0) {
    std::printf("absent        %d images without the target\n", summary.images_without_target);
  }
  std::printf("time          %.1f s (%.1f images/s)\n", summary.seconds,
              summary.seconds > 0.0 ? summary.images / summary.seconds : 0.0);
  std::printf("dataset       %s\n", summary.out_dir.string().c_str());
}

void RunSynth(const SynthArgs& args) {
  const SynthOptions options = BuildOptions(args);
  const SynthSummary summary =
      RunWithProgress([&](const JobControl& job) { return SynthesizeScenes(options, job); });
  PrintSummary(summary);
}

}  // namespace

void AddSynthCommand(CLI::App& app) {
  auto args = std::make_shared<SynthArgs>();
  CLI::App* command = app.add_subcommand(
      "synth", "Generate synthetic RGB-D scenes with exact ground truth as a BOP dataset");
  command
      ->add_option("--models", args->models,
                   "BOP models folder (obj_NNNNNN.ply), or one PLY file for one object id")
      ->required();
  SynthOptions& o = args->options;
  command->add_option("--obj-ids", o.obj_ids, "Target object ids, one per image, cycled")
      ->delimiter(',')
      ->required();
  command->add_option("--scenes", o.scenes, "Number of images")->capture_default_str();
  command->add_option("--seed", o.seed, "Random seed (same seed, same dataset)")
      ->capture_default_str();
  command->add_option("--dmin", o.dmin_mm, "Nearest camera-to-target distance (mm)")
      ->capture_default_str();
  command->add_option("--dmax", o.dmax_mm, "Farthest camera-to-target distance (mm)")
      ->capture_default_str();
  command->add_option("--elevation-min", o.elevation_min_deg, "Lowest camera elevation (deg)")
      ->capture_default_str();
  command->add_option("--elevation-max", o.elevation_max_deg, "Highest camera elevation (deg)")
      ->capture_default_str();
  command->add_option("--roll-max", o.roll_max_deg, "Camera roll up to +- this (deg)")
      ->capture_default_str();
  command
      ->add_option("--min-visibility", o.min_target_visibility,
                   "Least visible share of the target's silhouette")
      ->capture_default_str();
  command
      ->add_option("--max-visibility", o.max_target_visibility,
                   "Below 1: every target partly hidden, at most this share visible")
      ->capture_default_str();
  command->add_option("--instances", o.instances, "Copies of the target in each image (1..5)")
      ->capture_default_str();
  command
      ->add_option("--absent", o.absent_fraction,
                   "Share of images without the target (clutter only), 0..1")
      ->capture_default_str();
  command->add_option("--backgrounds", args->backgrounds,
                      "Folder of photos for the table texture (default: procedural)");
  command->add_option("--camera", args->camera,
                      "BOP camera.json (default: camera.json beside the models folder)");
  command
      ->add_option("--clutter", o.clutter,
                   "Up to this many other models and primitives around the target (0..5)")
      ->capture_default_str();
  command->add_flag("--no-noise", args->no_noise, "Write the noiseless renders (no sensor model)");
  command
      ->add_option("--up-axis", args->up_axis,
                   "The models' axis that points up when they stand on the table")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z"}))
      ->capture_default_str();
  command->add_flag("--any-orientation", o.any_orientation,
                    "Models lie in any orientation (uniformly random rotation), not upright");
  command->add_option("--threads", o.threads, "Worker threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--out", args->out, "Dataset folder to create (new or empty)")->required();
  command->callback([args] { RunSynth(*args); });
}

}  // namespace layermod::cli
