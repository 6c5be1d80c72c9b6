// SPDX-License-Identifier: MIT
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/detector_tuning.h"
#include "cli/image_output.h"
#include "dataset/bop.h"
#include "pipeline/capture_io.h"
#include "pipeline/detector.h"
#include "pipeline/overlays.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod::cli {
namespace {
namespace fs = std::filesystem;

struct DetectArgs {
  std::vector<std::string> archives;
  std::string bop_dir;
  int scene_id = -1;
  int frame_id = -1;
  std::string color;
  std::string depth;
  std::string camera;
  double depth_scale = 1.0;
  std::string float_depth_unit = "mm";
  std::string mode = "scene-patch";
  int max_instances = 1;
  int blocks = CoarsePositioningOptions{}.max_blocks;
  DetectorTuning tuning;
  float threshold = MatchOptions{}.threshold_percent;
  std::string json_out;
  std::string overlay_out;
  std::string stages_dir;
};

BopScene FindScene(const std::string& dir, int scene_id) {
  for (BopScene& scene : ListBopScenes(dir)) {
    if (scene.scene_id == scene_id) return std::move(scene);
  }
  throw Error("'" + dir + "': there is no scene " + std::to_string(scene_id));
}

Capture LoadRequestedCapture(const DetectArgs& args) {
  if (!args.bop_dir.empty()) {
    if (args.scene_id < 0 || args.frame_id < 0) {
      throw Error("--bop needs --scene and --frame");
    }
    const BopScene scene = FindScene(args.bop_dir, args.scene_id);
    const BopFrame frame = LoadBopFrame(scene, args.frame_id);
    return Capture{frame.color, frame.depth_mm, frame.camera};
  }
  if (args.color.empty() || args.camera.empty()) {
    throw Error(
        "give either --bop DIR --scene S --frame ID, or --color C.png --camera camera.json "
        "[--depth D.png]");
  }
  CaptureFiles files;
  files.color = args.color;
  files.depth = args.depth;
  files.camera = args.camera;
  files.depth_scale = args.depth_scale;
  files.float_depth_unit =
      args.float_depth_unit == "m" ? DepthUnit::kMetre : DepthUnit::kMillimetre;
  return LoadCapture(files);
}

nlohmann::json DetectionJson(const Detection& detection) {
  std::vector<double> rotation;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) rotation.push_back(detection.cam_from_model.R(row, col));
  }
  const Eigen::Vector3d& t = detection.cam_from_model.t;
  return {{"obj_id", detection.obj_id},
          {"name", detection.name},
          {"score", detection.score},
          {"cam_R_m2c", rotation},
          {"cam_t_m2c", {t.x(), t.y(), t.z()}},
          {"template_id", detection.template_id},
          {"layer_mm", detection.layer_depth_mm},
          {"icp",
           {{"rmse_mm", detection.icp.rmse_mm},
            {"inlier_ratio", detection.icp.inlier_ratio},
            {"iterations", detection.icp.iterations}}},
          {"verification",
           {{"depth_inlier_ratio", detection.verification.depth_inlier_ratio},
            {"depth_fit", detection.verification.depth_fit},
            {"visible_ratio", detection.verification.visible_ratio},
            {"color_agreement", detection.verification.color_agreement}}}};
}

nlohmann::json ResultJson(const DetectionResult& result, DetectionMode mode) {
  nlohmann::json json;
  json["mode"] = std::string(ModeName(mode));
  json["detections"] = nlohmann::json::array();
  for (const Detection& detection : result.detections)
    json["detections"].push_back(DetectionJson(detection));
  const StageTimings& t = result.timings;
  json["timings_ms"] = {{"prepare", t.prepare_ms}, {"regions", t.regions_ms},
                        {"coarse", t.coarse_ms},   {"match", t.match_ms},
                        {"pose", t.pose_ms},       {"total", t.total_ms}};
  return json;
}

void WriteStageImages(const fs::path& dir, const Capture& capture, const DetectionResult& result,
                      const Detector& detector) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw IoError("'" + dir.string() + "': cannot create directory (" + ec.message() + ")");
  for (const ObjectDiagnostics& diagnostics : result.diagnostics) {
    const ArchiveObject& object = detector.Object(diagnostics.obj_id);
    const std::string prefix = "obj" + std::to_string(diagnostics.obj_id) + "_";
    if (!diagnostics.division.blocks.empty() || !diagnostics.coarse.evaluated.empty()) {
      WritePng(dir / (prefix + "1_regions.png"),
               DrawRegionDivision(capture.color, diagnostics, object));
      WritePng(dir / (prefix + "2_coarse.png"), DrawCoarsePositioning(capture.color, diagnostics));
    }
    WritePng(dir / (prefix + "3_matches.png"),
             DrawMatches(capture.color, diagnostics, detector.ArchiveOf(diagnostics.obj_id)));
  }
  WritePng(dir / "4_poses.png",
           DrawPoses(capture.color, result.detections, detector, capture.camera));
}

void PrintDetections(const DetectionResult& result) {
  if (result.detections.empty()) std::printf("no detection\n");
  for (const Detection& d : result.detections) {
    const Eigen::Vector3d& t = d.cam_from_model.t;
    std::printf(
        "obj %d %-12s score %5.1f%%  t = (%.1f, %.1f, %.1f) mm  layer %.0f mm  template %u\n",
        d.obj_id, d.name.c_str(), d.score, t.x(), t.y(), t.z(), d.layer_depth_mm, d.template_id);
  }
  const StageTimings& t = result.timings;
  std::printf("time %.1f ms (prepare %.1f, regions %.1f, coarse %.1f, match %.1f, pose %.1f)\n",
              t.total_ms, t.prepare_ms, t.regions_ms, t.coarse_ms, t.match_ms, t.pose_ms);
}

void RunDetect(const DetectArgs& args) {
  DetectorOptions options;
  options.mode = ParseDetectionMode(args.mode);
  options.max_instances = args.max_instances;
  options.coarse.max_blocks = args.blocks;
  args.tuning.ApplyTo(options);
  options.match.threshold_percent = args.threshold;
  options.Validate();
  for (const std::string& path : {args.json_out, args.overlay_out}) {
    if (!path.empty()) CheckWritableTarget(path);
  }
  std::vector<TemplateArchive> archives;
  for (const std::string& path : args.archives) archives.push_back(ReadArchive(path));
  const Detector detector(std::move(archives));
  const Capture capture = LoadRequestedCapture(args);
  const DetectionResult result = detector.Detect(capture, options);
  PrintDetections(result);
  if (!args.json_out.empty()) {
    WriteFileAtomically(args.json_out, ResultJson(result, options.mode).dump(2) + "\n");
  }
  if (!args.overlay_out.empty()) {
    WritePng(args.overlay_out,
             DrawPoses(capture.color, result.detections, detector, capture.camera));
  }
  if (!args.stages_dir.empty()) WriteStageImages(args.stages_dir, capture, result, detector);
}

}  // namespace

void AddDetectCommand(CLI::App& app) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* command = app.add_subcommand("detect", "Detect objects and estimate their 6D pose");
  command->add_option("--archive", args->archives, "Template archive(s) (*.layermod)")->required();
  command->add_option("--bop", args->bop_dir,
                      "BOP dataset split directory (holding scene folders)");
  command->add_option("--scene", args->scene_id, "BOP scene id");
  command->add_option("--frame", args->frame_id, "BOP image id");
  command->add_option("--color", args->color, "Colour image (PNG/JPEG)");
  command->add_option("--depth", args->depth, "Depth image (16-bit PNG, mm)");
  command->add_option("--camera", args->camera, "Camera file (BOP camera.json)");
  command->add_option("--depth-scale", args->depth_scale, "16-bit depth value * scale = mm")
      ->capture_default_str();
  command
      ->add_option("--float-depth-unit", args->float_depth_unit,
                   "Unit of a 32-bit float depth image: mm or m")
      ->check(CLI::IsMember({"mm", "m"}));
  command->add_option("--mode", args->mode, "scene-patch, exhaustive or color-only")
      ->check(CLI::IsMember({"scene-patch", "exhaustive", "color-only"}))
      ->capture_default_str();
  command->add_option("--instances", args->max_instances, "Detections kept per object")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--blocks", args->blocks, "Scene blocks kept by coarse positioning (0 = all)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  AddDetectorTuningOptions(command, args->tuning);
  command->add_option("--threshold", args->threshold, "Match similarity threshold (percent)")
      ->check(CLI::Range(1.0f, 100.0f))
      ->capture_default_str();
  command->add_option("--json", args->json_out, "Write detections as JSON");
  command->add_option("--overlay", args->overlay_out, "Write the final poses drawn on the image");
  command->add_option("--overlay-stages", args->stages_dir,
                      "Write region division, coarse positioning, matches and poses images");
  command->callback([args] { RunDetect(*args); });
}

}  // namespace layermod::cli
