// SPDX-License-Identifier: MIT
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/progress_bar.h"
#include "dataset/bop_json.h"
#include "geometry/resting_poses.h"
#include "geometry/units.h"
#include "geometry/up_axis.h"
#include "mesh/model.h"
#include "mesh/model_resting_poses.h"
#include "pipeline/training.h"
#include "templates/archive.h"
#include "util/atomic_file.h"
#include "util/log.h"
#include "util/quoted.h"

namespace layermod::cli {
namespace {

// The dry run lists this many resting poses at most, and none rarer than this: the slivers of a
// faceted surface would bury the few poses worth choosing.
constexpr std::size_t kListedRestingPoses = 5;
constexpr double kListedRestProbability = 0.01;

struct TrainArgs {
  bool dry_run = false;
  std::string model;
  std::string name;
  std::string camera;
  std::string profile;
  std::string out;
  std::string units = "mm";
  std::string azimuth;
  std::string elevation;
  std::string roll;
  std::string up_axis;
  std::string up_rotation;
  std::string view_preset;
  std::int32_t obj_id = 1;
  double dmin_mm = 0.0;
  double dmax_mm = 0.0;
  double even_views_deg = -1.0;
  int color_features = -1;
  int normal_features = -1;
  int threads = 0;
  std::size_t max_triangles = TrainingRequest{}.max_render_triangles;
};

// --up-rotation FILE: a JSON file holding {"upright_from_model": [9 numbers, row-major]}.
Eigen::Matrix3d LoadUprightRotation(const std::string& path) {
  const nlohmann::json json = bop_internal::ParseJsonObjectFile(path);
  TrainingProfile probe;
  try {
    probe = TrainingProfileFromJson({{"views", json}});
  } catch (const FormatError& error) {
    throw FormatError(Quoted(path) + ": " + error.what());
  }
  if (!json.contains("upright_from_model") && !json.contains("up_axis")) {
    throw FormatError(Quoted(path) + ": needs \"upright_from_model\": [9 numbers, row-major]");
  }
  return probe.views.upright_from_model;
}

// Profile: the file if given, else the defaults; explicit flags win.
TrainingProfile BuildProfile(const TrainArgs& args) {
  TrainingProfile profile =
      args.profile.empty() ? TrainingProfile{} : LoadTrainingProfile(args.profile);
  if (args.dmin_mm != 0.0) profile.depth_min_mm = args.dmin_mm;
  if (args.dmax_mm != 0.0) profile.depth_max_mm = args.dmax_mm;
  ViewSamplingOptions& views = profile.views;
  if (!args.up_rotation.empty()) views.upright_from_model = LoadUprightRotation(args.up_rotation);
  if (!args.up_axis.empty()) views.upright_from_model = UprightFromUpAxis(args.up_axis);
  if (!args.view_preset.empty()) views = ViewPreset(args.view_preset, views.upright_from_model);
  if (!args.azimuth.empty()) views.azimuth = AngleRange::Parse(args.azimuth, "--azimuth");
  if (!args.elevation.empty()) views.elevation = AngleRange::Parse(args.elevation, "--elevation");
  if (!args.roll.empty()) views.roll = AngleRange::Parse(args.roll, "--roll");
  // An explicit az/el grid means grid sampling unless --even-views is also given.
  if (!args.azimuth.empty() || !args.elevation.empty()) views.even_spacing_deg = 0.0;
  if (args.even_views_deg >= 0.0) views.even_spacing_deg = args.even_views_deg;
  if (args.color_features >= 0) profile.features.color_features = args.color_features;
  if (args.normal_features >= 0) profile.features.normal_features = args.normal_features;
  profile.Validate();
  return profile;
}

void PrintSummary(const TrainingSummary& summary, const std::string& out) {
  std::printf("radius        %.2f mm (diameter %.2f mm)\n", summary.radius_mm,
              2.0 * summary.radius_mm);
  std::printf("depth layers  %d\n", summary.layers);
  std::printf("templates     %zu (%zu weak)\n", summary.templates, summary.weak_templates);
  std::printf("time          %.2f s (%.0f templates/s)\n", summary.seconds,
              summary.TemplatesPerSecond());
  std::printf("archive       %s\n", out.c_str());
}

std::string UpAxisText(const Eigen::Matrix3d& upright_from_model) {
  const Eigen::Vector3d up = UpDirectionInModel(upright_from_model);
  char text[96];
  std::snprintf(text, sizeof text, "model (%.3f, %.3f, %.3f)", up.x(), up.y(), up.z());
  return UpAxisName(upright_from_model).value_or(text);
}

std::string PercentText(double probability) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f %%", 100.0 * probability);
  return text;
}

// "+z 41 %, -z 22 %, tilted (0.12, -0.70, 0.70) 6 %".
std::string RestingPosesText(const RestingPoses& rest) {
  if (rest.poses.empty()) return "none (the mesh encloses no volume)";
  std::string text;
  for (std::size_t i = 0; i < rest.poses.size() && i < kListedRestingPoses; ++i) {
    const RestingPose& pose = rest.poses[i];
    if (pose.probability < kListedRestProbability) break;  // most likely first
    if (!text.empty()) text += ", ";
    text += RestingPoseName(pose) + " " + PercentText(pose.probability);
  }
  if (text.empty()) text = "none above " + PercentText(kListedRestProbability);
  if (!rest.from_closed_mesh) text += " (mesh not closed: centre of mass of its hull)";
  return text;
}

// The view envelope is measured from the up axis, so one the part does not rest on is usually a
// mistake; only a warning, as a part held in a gripper can be trained any way up.
void WarnIfUpAxisIsNoRestingPose(const RestingPoses& rest, const Eigen::Matrix3d& upright,
                                 const Model& model) {
  const std::vector<RestingPose> likely = LikelyRestingPoses(rest);
  if (likely.empty() || IsLikelyRestingUp(rest, upright)) return;
  std::string suggested;
  for (std::size_t i = 0; i < likely.size() && i < kListedRestingPoses; ++i) {
    if (!suggested.empty()) suggested += ", ";
    suggested += RestingPoseName(likely[i]) + " (" + PercentText(likely[i].probability) + ")";
  }
  const std::optional<RestingPose> along = RestingPoseAlong(rest, upright);
  const std::string how = along ? "is a rare resting pose (" + PercentText(along->probability) + ")"
                                : "is not a stable resting pose";
  std::fprintf(stderr, "layermod: warning: up axis %s %s of %s; it rests most likely on %s\n",
               UpAxisText(upright).c_str(), how.c_str(), model.source.filename().string().c_str(),
               suggested.c_str());
}

// The plan alone: what a run would make, and roughly how much memory it takes.
void PrintPlan(const TrainingPlan& plan, const TrainingRequest& request, const RestingPoses& rest) {
  std::printf("radius        %.2f mm (diameter %.2f mm)\n", plan.radius_mm, 2.0 * plan.radius_mm);
  std::printf("depth layers  %zu:", plan.layer_depths_mm.size());
  for (double depth_mm : plan.layer_depths_mm) std::printf(" %.0f", depth_mm);
  std::printf(" mm\n");
  std::printf("views         %zu per layer\n", plan.views.size());
  std::printf("up axis       %s\n", UpAxisText(request.profile.views.upright_from_model).c_str());
  std::printf("resting poses %s\n", RestingPosesText(rest).c_str());
  std::printf("templates     %zu\n", plan.TemplateCount());
  std::printf("memory        about %.1f MiB for the templates\n",
              static_cast<double>(plan.EstimatedBytes(request.profile.features)) / (1 << 20));
}

void RunTrain(const TrainArgs& args) {
  if (!args.dry_run && args.out.empty()) throw CLI::RequiredError("--out");
  TrainingRequest request;
  request.obj_id = args.obj_id;
  request.name = args.name;
  request.camera = LoadCameraJson(args.camera);
  request.profile = BuildProfile(args);
  request.threads = args.threads;
  request.max_render_triangles = args.max_triangles;
  if (!args.dry_run) CheckWritableTarget(args.out);  // fail before the work, not after it

  LoadModelOptions load_options;
  load_options.units = ParseLengthUnit(args.units);
  const Model model = LoadModel(args.model, load_options);
  if (request.name.empty()) request.name = model.source.stem().string();
  const TrainingPlan plan = PlanTraining(model, request);
  const RestingPoses rest = SuggestRestingPoses(model);
  WarnIfUpAxisIsNoRestingPose(rest, request.profile.views.upright_from_model, model);
  if (args.dry_run) {
    PrintPlan(plan, request, rest);
    return;
  }
  // Ctrl-C is caught from here on: it cancels the job and nothing is written.
  CancelToken cancel;
  InterruptScope interrupt(cancel);
  std::fprintf(stderr, "training %zu templates: %zu views x %zu depth layers (radius %.2f mm)\n",
               plan.TemplateCount(), plan.views.size(), plan.layer_depths_mm.size(),
               plan.radius_mm);

  ProgressBar bar;
  const JobControl job([&bar](std::size_t done, std::size_t total,
                              std::string_view stage) { bar.Update(done, total, stage); },
                       &cancel);
  TrainingResult result = TrainTemplates(model, request, job);
  bar.Finish();
  job.ThrowIfCancelled();
  WriteArchive(args.out, result.archive);
  PrintSummary(result.summary, args.out);
}

}  // namespace

void AddTrainCommand(CLI::App& app) {
  auto args = std::make_shared<TrainArgs>();
  CLI::App* command = app.add_subcommand(
      "train", "Train multi-scale LineMOD templates of a mesh into a .layermod archive");
  command->add_option("--model", args->model, "Mesh file (PLY, STL, OBJ, OFF, glTF, ...)")
      ->required();
  command->add_option("--obj-id", args->obj_id, "Object id stored with the templates")
      ->capture_default_str();
  command->add_option("--name", args->name, "Object name (default: mesh file name)");
  command->add_option("--camera", args->camera, "BOP camera.json (fx fy cx cy width height)")
      ->required();
  command->add_option("--profile", args->profile, "Training profile JSON (flags override it)");
  command->add_option("--dmin", args->dmin_mm, "Nearest object distance D_min (mm)");
  command->add_option("--dmax", args->dmax_mm, "Farthest object distance D_max (mm)");
  command
      ->add_option("--up-axis", args->up_axis,
                   "The model axis that points up when the part stands as used; the view angles "
                   "are measured from it (default +z)")
      ->check(CLI::IsMember({"+x", "-x", "+y", "-y", "+z", "-z"}));
  command->add_option("--up-rotation", args->up_rotation,
                      "JSON file with an arbitrary model-to-upright rotation "
                      "{\"upright_from_model\": [9 numbers]}");
  command
      ->add_option("--view-preset", args->view_preset,
                   "tabletop (upper hemisphere, roll -45..45) or full (whole sphere, any roll); "
                   "--azimuth/--elevation/--roll/--even-views override it")
      ->check(CLI::IsMember({"tabletop", "full"}));
  command->add_option("--azimuth", args->azimuth, "Azimuth grid min:step:max (deg)");
  command->add_option("--elevation", args->elevation, "Elevation grid min:step:max (deg)");
  command->add_option("--roll", args->roll, "In-plane rotation grid min:step:max (deg)");
  command->add_option("--even-views", args->even_views_deg,
                      "Even view-sphere sampling with this spacing (deg); 0 = az/el grid");
  command->add_option("--color-features", args->color_features,
                      "Colour-gradient features per template");
  command->add_option("--normal-features", args->normal_features,
                      "Depth-normal features per template");
  command
      ->add_option("--max-triangles", args->max_triangles,
                   "Simplify heavier meshes to this many triangles for rendering (0 = never)")
      ->capture_default_str();
  command->add_option("--units", args->units, "Units of the mesh file: mm or m")
      ->check(CLI::IsMember({"mm", "m"}))
      ->capture_default_str();
  command->add_option("--threads", args->threads, "Worker threads (0 = all cores)")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--out", args->out, "Output archive (*.layermod)");
  command->add_flag(
      "--dry-run", args->dry_run,
      "Print the plan (layers, views, resting poses, templates, memory) and stop; no --out "
      "needed");
  command->callback([args] { RunTrain(*args); });
}

}  // namespace layermod::cli
