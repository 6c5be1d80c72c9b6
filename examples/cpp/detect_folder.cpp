// SPDX-License-Identifier: MIT
// Loads archives once and detects in every frame of a folder, printing poses and per-frame times.
//   detect_folder FOLDER ARCHIVE... [--options JSON]
// FOLDER is a BOP scene (rgb/, depth/, scene_camera.json; the camera is the dataset's
// camera.json two levels up) or a folder of NAME_color.png / NAME_depth.png pairs (16-bit mm)
// with a camera.json.
#include <layermod/archive.h>
#include <layermod/capture.h>
#include <layermod/detector.h>
#include <layermod/error.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fs = std::filesystem;

struct FrameFiles {
  std::string name;
  fs::path color;
  fs::path depth;
  double depth_scale = 1.0;
};

struct Folder {
  fs::path camera;
  std::vector<FrameFiles> frames;
};

Folder ListBopScene(const fs::path& scene) {
  Folder folder{scene.parent_path().parent_path() / "camera.json", {}};
  std::ifstream in(scene / "scene_camera.json");
  const nlohmann::json cameras = nlohmann::json::parse(in);
  for (const auto& [id, entry] : cameras.items()) {
    char stem[16];
    std::snprintf(stem, sizeof(stem), "%06d.png", std::stoi(id));
    folder.frames.push_back(
        {id, scene / "rgb" / stem, scene / "depth" / stem, entry.value("depth_scale", 1.0)});
  }
  std::sort(folder.frames.begin(), folder.frames.end(),
            [](const FrameFiles& a, const FrameFiles& b) {
              return std::stoi(a.name) < std::stoi(b.name);
            });
  return folder;
}

Folder ListPairs(const fs::path& dir) {
  Folder folder{dir / "camera.json", {}};
  const std::string suffix = "_color.png";
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string file = entry.path().filename().string();
    if (file.size() <= suffix.size() || !file.ends_with(suffix)) continue;
    const std::string name = file.substr(0, file.size() - suffix.size());
    folder.frames.push_back({name, entry.path(), dir / (name + "_depth.png"), 1.0});
  }
  std::sort(folder.frames.begin(), folder.frames.end(),
            [](const FrameFiles& a, const FrameFiles& b) { return a.name < b.name; });
  return folder;
}

void PrintResult(const std::string& name, const layermod::api::DetectionResult& result,
                 double wall_ms) {
  std::printf("frame %s: %zu detection(s), %.1f ms (detector stages %.1f ms)\n", name.c_str(),
              result.detections.size(), wall_ms, result.timings.total_ms);
  for (const layermod::api::Detection& d : result.detections) {
    std::printf("  obj %d %s score %.1f%% t = (%.1f, %.1f, %.1f) mm R = [", d.obj_id,
                d.name.c_str(), d.score, d.t_mm.x(), d.t_mm.y(), d.t_mm.z());
    for (int i = 0; i < 9; ++i) std::printf(i ? " %.4f" : "%.4f", d.R(i / 3, i % 3));
    std::printf("] layer %.0f mm\n", d.layer_depth_mm);
  }
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s FOLDER ARCHIVE... [--options JSON]\n", argv[0]);
    return 2;
  }
  try {
    const fs::path dir = argv[1];
    std::vector<layermod::api::Archive> archives;
    std::string options = "{}";
    for (int i = 2; i < argc; ++i) {
      if (std::string(argv[i]) == "--options" && i + 1 < argc) {
        options = argv[++i];
      } else {
        archives.push_back(layermod::api::Archive::Load(argv[i]));  // once, for every frame
      }
    }
    const layermod::api::Detector detector(std::move(archives), options);
    const Folder folder =
        fs::exists(dir / "scene_camera.json") ? ListBopScene(dir) : ListPairs(dir);
    if (folder.frames.empty()) {
      std::fprintf(stderr, "%s: no frames (expected a BOP scene or *_color.png)\n", argv[1]);
      return 1;
    }
    for (const FrameFiles& frame : folder.frames) {
      const layermod::api::Capture capture =
          layermod::api::LoadCapture(frame.color, frame.depth, folder.camera, frame.depth_scale);
      const auto start = std::chrono::steady_clock::now();
      const layermod::api::DetectionResult result = detector.Detect(capture);
      const std::chrono::duration<double, std::milli> wall =
          std::chrono::steady_clock::now() - start;
      PrintResult(frame.name, result, wall.count());
    }
  } catch (const layermod::Error& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  } catch (const nlohmann::json::exception& error) {
    std::fprintf(stderr, "error: scene_camera.json: %s\n", error.what());
    return 1;
  }
  return 0;
}
