// SPDX-License-Identifier: MIT
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/detector_flags.h"
#include "cli/image_output.h"
#include "dataset/bop.h"
#include "pipeline/capture_io.h"
#include "pipeline/detection_json.h"
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
  DetectorFlags detector;
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

cv::Mat DimmedColor(const Capture& capture) {
  cv::Mat canvas = capture.color.clone();
  DimColor(canvas);
  return canvas;
}

cv::Mat PosesOverColor(const Capture& capture, const DetectionResult& result,
                       const Detector& detector) {
  cv::Mat canvas = capture.color.clone();
  DrawPoses(canvas, result.detections, detector, capture.camera);
  return canvas;
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
      cv::Mat regions = DimmedColor(capture);
      DrawRegionDivision(regions, diagnostics, object);
      DrawLayerLegend(regions, object);
      WritePng(dir / (prefix + "1_regions.png"), regions);
      cv::Mat coarse = DimmedColor(capture);
      DrawCoarsePositioning(coarse, diagnostics);
      DrawCoarseLegend(coarse);
      WritePng(dir / (prefix + "2_coarse.png"), coarse);
    }
    cv::Mat matches = DimmedColor(capture);
    DrawMatches(matches, diagnostics, detector.ArchiveOf(diagnostics.obj_id));
    WritePng(dir / (prefix + "3_matches.png"), matches);
  }
  WritePng(dir / "4_poses.png", PosesOverColor(capture, result, detector));
}

void PrintDetections(const DetectionResult& result) {
  if (result.detections.empty()) std::printf("no detection\n");
  for (const Detection& d : result.detections) {
    const Eigen::Vector3d& t = d.cam_from_model.t;
    std::printf(
        "obj %d %-12s confidence %.2f  score %5.1f%%  t = (%.1f, %.1f, %.1f) mm  layer %.0f mm  "
        "template %u\n",
        d.obj_id, d.name.c_str(), d.confidence, d.score, t.x(), t.y(), t.z(), d.layer_depth_mm,
        d.template_id);
  }
  const StageTimings& t = result.timings;
  std::printf("time %.1f ms (prepare %.1f, regions %.1f, coarse %.1f, match %.1f, pose %.1f)\n",
              t.total_ms, t.prepare_ms, t.regions_ms, t.coarse_ms, t.match_ms, t.pose_ms);
}

void RunDetect(const DetectArgs& args) {
  const DetectorOptions options = args.detector.Resolve();
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
    WriteFileAtomically(args.json_out, DetectionResultToJson(result, options.mode).dump(2) + "\n");
  }
  if (!args.overlay_out.empty()) {
    WritePng(args.overlay_out, PosesOverColor(capture, result, detector));
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
  args->detector.AddTo(command);
  command->add_option("--json", args->json_out, "Write detections as JSON");
  command->add_option("--overlay", args->overlay_out, "Write the final poses drawn on the image");
  command->add_option("--overlay-stages", args->stages_dir,
                      "Write region division, coarse positioning, matches and poses images");
  command->callback([args] { RunDetect(*args); });
}

}  // namespace layermod::cli
