// SPDX-License-Identifier: MIT
// Writes a seed corpus for every fuzz target into OUTDIR/<target>/, from files the project makes
// itself (a small archive trained on the sample part, a profile, a rendered-looking capture, a
// tiny BOP scene, meshes in each format) and, when given, from the real LineMOD-Occluded files
// of a shared data folder (read in place, copied into OUTDIR only).
//   layermod_fuzz_seeds OUTDIR [SHARED_DATA_DIR]
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dataset/bop_fixtures.h"
#include "fuzz/fuzz_input.h"
#include "mesh/model.h"
#include "mesh/sample_part.h"
#include "pipeline/training.h"
#include "support/test_cameras.h"
#include "templates/archive.h"
#include "util/atomic_file.h"

namespace {
namespace fs = std::filesystem;
using namespace layermod;

void WriteSeed(const fs::path& dir, const std::string& name, const std::string& bytes) {
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << bytes;
}

std::string EncodePng(const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  cv::imencode(".png", image, bytes);
  return {bytes.begin(), bytes.end()};
}

TrainingRequest TinyRequest() {
  TrainingRequest request;
  request.name = "bracket";
  request.camera = test::TinyCamera();
  request.camera.fx = request.camera.fy = 300.0;
  request.camera.width = 320;
  request.camera.height = 240;
  request.camera.cx = 159.5;
  request.camera.cy = 119.5;
  request.profile.depth_min_mm = 600.0;
  request.profile.depth_max_mm = 700.0;
  request.profile.views.even_spacing_deg = 0.0;
  request.profile.views.azimuth = {0.0, 120.0, 240.0};
  request.profile.views.elevation = {30.0, 30.0, 60.0};
  request.profile.views.roll = {0.0, 10.0, 0.0};
  return request;
}

void WriteArchiveSeeds(const fs::path& dir, const fs::path& work) {
  const fs::path mesh = work / "bracket.ply";
  SaveModelPly(mesh, MakeSampleBracket());
  const TrainingResult result = TrainTemplates(LoadModel(mesh), TinyRequest());
  WriteArchive(work / "tiny.layermod", result.archive);
  WriteSeed(dir, "tiny.layermod", ReadFileBytes(work / "tiny.layermod"));
  SaveTrainingProfile(work / "profile.json", TinyRequest().profile);
}

void WriteProfileSeeds(const fs::path& dir, const fs::path& work) {
  WriteSeed(dir, "tiny.json", ReadFileBytes(work / "profile.json"));
  SaveTrainingProfile(work / "default.json", TrainingProfile{});
  WriteSeed(dir, "default.json", ReadFileBytes(work / "default.json"));
  WriteSeed(dir, "partial.json", R"({"depth_min_mm": 650, "views": {"roll": "-30:15:30"}})");
}

void WriteCaptureSeeds(const fs::path& dir) {
  const PinholeCamera camera = test::TinyCamera();
  cv::Mat depth(camera.height, camera.width, CV_16U, cv::Scalar(900));
  cv::rectangle(depth, {20, 12, 24, 20}, cv::Scalar(700), cv::FILLED);
  depth(cv::Rect(0, 0, 6, 6)).setTo(0);
  cv::Mat color(camera.height, camera.width, CV_8UC3, cv::Scalar(90, 110, 130));
  cv::rectangle(color, {20, 12, 24, 20}, cv::Scalar(200, 60, 40), cv::FILLED);
  nlohmann::json camera_json = CameraJson(camera);
  camera_json["depth_scale"] = 1.0;
  const std::string json = camera_json.dump();
  WriteSeed(dir, "capture", fuzz::JoinParts({json, EncodePng(depth), EncodePng(color)}));
  cv::Mat depth8;
  depth.convertTo(depth8, CV_8U, 0.25);
  WriteSeed(dir, "depth-8bit", fuzz::JoinParts({json, EncodePng(depth8), EncodePng(color)}));
  cv::Mat grey;
  cv::cvtColor(color, grey, cv::COLOR_BGR2GRAY);
  WriteSeed(dir, "grey-colour", fuzz::JoinParts({json, EncodePng(depth), EncodePng(grey)}));
}

std::string FileOrEmpty(const fs::path& path) {
  return fs::is_regular_file(path) ? ReadFileBytes(path) : std::string();
}

void WriteBopSeed(const fs::path& dir, const std::string& name, const fs::path& scene,
                  const fs::path& models_info, const std::string& stem) {
  WriteSeed(dir, name,
            fuzz::JoinParts({FileOrEmpty(scene / "scene_camera.json"),
                             FileOrEmpty(scene / "scene_gt.json"),
                             FileOrEmpty(scene / "scene_gt_info.json"), FileOrEmpty(models_info),
                             FileOrEmpty(scene / "rgb" / (stem + ".png")),
                             FileOrEmpty(scene / "depth" / (stem + ".png"))}));
}

void WriteBopSeeds(const fs::path& dir, const fs::path& work, const fs::path& shared) {
  const fs::path scene = test::WriteTinyScene(work / "bop");
  test::WriteText(
      work / "models_info.json",
      R"({"7": {"diameter": 120.5, "min_x": -40, "min_y": -40, "min_z": -30,)"
      R"( "size_x": 80, "size_y": 80, "size_z": 60,)"
      R"( "symmetries_discrete": [[-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]]}})");
  WriteBopSeed(dir, "tiny-scene", scene, work / "models_info.json", "000000");
  const fs::path lmo = shared / "lmo-dev";
  if (!shared.empty() && fs::is_directory(lmo / "test" / "000002")) {
    WriteBopSeed(dir, "lmo-scene", lmo / "test" / "000002", lmo / "models" / "models_info.json",
                 "none");
  }
}

void WriteMeshSeeds(const fs::path& dir, const fs::path& work) {
  // The first byte picks the extension (ply, stl, obj, off); see mesh_fuzzer.cpp.
  WriteSeed(dir, "bracket.ply", std::string(1, '\0') + ReadFileBytes(work / "bracket.ply"));
  WriteSeed(dir, "tetra.ply",
            std::string(1, '\0') +
                "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
                "0 0 0 255 0 0\n10 0 0 0 255 0\n0 10 0 0 0 255\n0 0 10 9 9 9\n"
                "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  WriteSeed(dir, "tetra.stl",
            std::string(1, '\1') +
                "solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 10 0\n"
                "vertex 10 0 0\nendloop\nendfacet\nfacet normal 0 -1 0\nouter loop\n"
                "vertex 0 0 0\nvertex 10 0 0\nvertex 0 0 10\nendloop\nendfacet\nendsolid t\n");
  WriteSeed(dir, "tetra.obj",
            std::string(1, '\2') +
                "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  WriteSeed(dir, "tetra.off",
            std::string(1, '\3') +
                "OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: layermod_fuzz_seeds OUTDIR [SHARED_DATA_DIR]\n");
    return 2;
  }
  const fs::path out = argv[1];
  const fs::path shared = argc == 3 ? fs::path(argv[2]) : fs::path();
  const fs::path work = out / ".work";
  fs::remove_all(out);
  fs::create_directories(work);
  try {
    WriteArchiveSeeds(out / "archive", work);
    WriteProfileSeeds(out / "profile", work);
    WriteCaptureSeeds(out / "capture");
    WriteBopSeeds(out / "bop", work, shared);
    WriteMeshSeeds(out / "mesh", work);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "layermod_fuzz_seeds: %s\n", error.what());
    return 1;
  }
  fs::remove_all(work);
  std::printf("seeds written to %s\n", out.string().c_str());
  return 0;
}
