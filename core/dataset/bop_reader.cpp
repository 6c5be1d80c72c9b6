// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cstdio>
#include <string>

#include "dataset/bop.h"
#include "dataset/bop_images.h"
#include "dataset/bop_json.h"
#include "util/error.h"

namespace layermod {
namespace fs = std::filesystem;
using bop_internal::JsonContext;

namespace {

using bop_internal::Quoted;

fs::path RequiredFile(const fs::path& scene_dir, const char* name) {
  fs::path path = scene_dir / name;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) {
    throw IoError(Quoted(path) + ": missing scene file (" + name + " is required in a BOP scene)");
  }
  return path;
}

std::string ImageContext(int image_id) { return "image " + std::to_string(image_id); }

void ReadSceneCamera(const fs::path& path, BopScene& scene) {
  const nlohmann::json json = bop_internal::ParseJsonObjectFile(path);
  const JsonContext file{path, ""};
  for (const auto& [key, entry] : json.items()) {
    const int image_id = bop_internal::ParseIdKey(key, file);
    const JsonContext context = file.Inside(ImageContext(image_id));
    const std::vector<double> k = bop_internal::NumbersField(entry, "cam_K", 9, context);
    BopFrameAnnotations annotations;
    annotations.camera.fx = k[0];
    annotations.camera.cx = k[2];
    annotations.camera.fy = k[4];
    annotations.camera.cy = k[5];
    if (k[0] <= 0.0 || k[4] <= 0.0) context.Fail("'cam_K' focal lengths must be positive");
    if (entry.contains("depth_scale")) {
      annotations.depth_scale = bop_internal::NumberField(entry, "depth_scale", context);
      if (annotations.depth_scale <= 0.0) context.Fail("'depth_scale' must be positive");
    }
    scene.annotations[image_id] = std::move(annotations);
    scene.image_ids.push_back(image_id);
  }
  std::sort(scene.image_ids.begin(), scene.image_ids.end());
}

// The annotations of `key`'s image, which scene_camera.json must list.
BopFrameAnnotations& AnnotationsOf(BopScene& scene, const std::string& key,
                                   const JsonContext& file) {
  const int image_id = bop_internal::ParseIdKey(key, file);
  const auto it = scene.annotations.find(image_id);
  if (it == scene.annotations.end()) {
    file.Fail(ImageContext(image_id) + " is not in scene_camera.json");
  }
  return it->second;
}

void ReadSceneGt(const fs::path& path, BopScene& scene) {
  const nlohmann::json json = bop_internal::ParseJsonObjectFile(path);
  const JsonContext file{path, ""};
  for (const auto& [key, entry] : json.items()) {
    BopFrameAnnotations& annotations = AnnotationsOf(scene, key, file);
    const JsonContext image = file.Inside("image " + key);
    if (!entry.is_array()) image.Fail("expected a list of object instances");
    for (std::size_t i = 0; i < entry.size(); ++i) {
      const JsonContext context = image.Inside("instance " + std::to_string(i));
      BopGroundTruth gt;
      gt.obj_id = bop_internal::IntField(entry[i], "obj_id", context);
      gt.cam_from_model = bop_internal::PoseFields(entry[i], "cam_R_m2c", "cam_t_m2c", context);
      annotations.gt.push_back(gt);
    }
  }
}

cv::Rect RectField(const nlohmann::json& entry, const char* key, const JsonContext& context) {
  const std::vector<double> box = bop_internal::NumbersField(entry, key, 4, context);
  return {static_cast<int>(box[0]), static_cast<int>(box[1]), static_cast<int>(box[2]),
          static_cast<int>(box[3])};
}

BopGtInfo ReadGtInfoEntry(const nlohmann::json& entry, const JsonContext& context) {
  BopGtInfo info;
  info.bbox_obj = RectField(entry, "bbox_obj", context);
  info.bbox_visib = RectField(entry, "bbox_visib", context);
  info.px_count_all = bop_internal::IntField(entry, "px_count_all", context);
  info.px_count_visib = bop_internal::IntField(entry, "px_count_visib", context);
  // Older BOP files lack px_count_valid.
  info.px_count_valid = entry.contains("px_count_valid")
                            ? bop_internal::IntField(entry, "px_count_valid", context)
                            : info.px_count_all;
  info.visib_fract = bop_internal::NumberField(entry, "visib_fract", context);
  return info;
}

void ReadSceneGtInfo(const fs::path& path, BopScene& scene) {
  const nlohmann::json json = bop_internal::ParseJsonObjectFile(path);
  const JsonContext file{path, ""};
  for (const auto& [key, entry] : json.items()) {
    BopFrameAnnotations& annotations = AnnotationsOf(scene, key, file);
    const JsonContext image = file.Inside("image " + key);
    if (!entry.is_array()) image.Fail("expected a list of object instances");
    if (entry.size() != annotations.gt.size()) {
      image.Fail(std::to_string(entry.size()) + " entries but scene_gt.json has " +
                 std::to_string(annotations.gt.size()));
    }
    for (std::size_t i = 0; i < entry.size(); ++i) {
      annotations.gt_info.push_back(
          ReadGtInfoEntry(entry[i], image.Inside("instance " + std::to_string(i))));
    }
  }
}

bool IsSceneDir(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  const bool digits = !name.empty() && std::all_of(name.begin(), name.end(), ::isdigit);
  std::error_code ec;
  return digits && entry.is_directory(ec) &&
         fs::is_regular_file(entry.path() / "scene_camera.json", ec);
}

std::vector<fs::path> SceneDirs(const fs::path& dir) {
  std::vector<fs::path> dirs;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    if (IsSceneDir(entry)) dirs.push_back(entry.path());
  }
  if (ec) throw IoError(Quoted(dir) + ": cannot list the folder (" + ec.message() + ")");
  return dirs;
}

fs::path FindColorImage(const BopScene& scene, int image_id) {
  const fs::path stem = scene.dir / "rgb" / BopIdName(image_id);
  for (const char* extension : {".png", ".jpg", ".jpeg"}) {
    fs::path path = stem;
    path += extension;
    std::error_code ec;
    if (fs::exists(path, ec)) return path;
  }
  fs::path expected = stem;
  expected += ".png";
  throw IoError(Quoted(expected) + ": colour image is missing (no .png or .jpg for image " +
                std::to_string(image_id) + ")");
}

}  // namespace

std::string BopIdName(int id) {
  char name[16];
  std::snprintf(name, sizeof(name), "%06d", id);
  return name;
}

std::string BopModelFileName(int obj_id) {
  char name[32];
  std::snprintf(name, sizeof(name), "obj_%06d.ply", obj_id);
  return name;
}

BopScene LoadBopScene(const fs::path& scene_dir) {
  std::error_code ec;
  if (!fs::is_directory(scene_dir, ec)) {
    throw IoError(Quoted(scene_dir) + ": scene folder does not exist");
  }
  BopScene scene;
  scene.dir = scene_dir;
  const std::string name = scene_dir.filename().string();
  try {
    scene.scene_id = bop_internal::ParseIdKey(name, JsonContext{scene_dir, ""});
  } catch (const FormatError&) {
    throw FormatError(Quoted(scene_dir) + ": a BOP scene folder is named by its id (000002)");
  }
  ReadSceneCamera(RequiredFile(scene_dir, "scene_camera.json"), scene);
  ReadSceneGt(RequiredFile(scene_dir, "scene_gt.json"), scene);
  const fs::path gt_info = scene_dir / "scene_gt_info.json";
  scene.has_gt_info = fs::is_regular_file(gt_info, ec);
  if (scene.has_gt_info) ReadSceneGtInfo(gt_info, scene);
  scene.has_depth = fs::is_directory(scene_dir / "depth", ec);
  return scene;
}

std::vector<BopScene> ListBopScenes(const fs::path& split_dir) {
  std::error_code ec;
  if (!fs::is_directory(split_dir, ec)) {
    throw IoError(Quoted(split_dir) + ": folder does not exist");
  }
  std::vector<fs::path> dirs = SceneDirs(split_dir);
  if (dirs.empty() && fs::is_directory(split_dir / "test", ec)) {
    dirs = SceneDirs(split_dir / "test");
  }
  if (dirs.empty()) {
    throw FormatError(Quoted(split_dir) +
                      ": no BOP scene folder (NNNNNN/ with scene_camera.json) here or in test/");
  }
  std::vector<BopScene> scenes;
  scenes.reserve(dirs.size());
  for (const fs::path& dir : dirs) scenes.push_back(LoadBopScene(dir));
  std::sort(scenes.begin(), scenes.end(),
            [](const BopScene& a, const BopScene& b) { return a.scene_id < b.scene_id; });
  return scenes;
}

BopFrame LoadBopFrame(const BopScene& scene, int image_id) {
  const auto it = scene.annotations.find(image_id);
  if (it == scene.annotations.end()) {
    throw Error("image " + std::to_string(image_id) + " is not in scene " +
                std::to_string(scene.scene_id) + " (" + Quoted(scene.dir) + ")");
  }
  const BopFrameAnnotations& annotations = it->second;
  BopFrame frame;
  frame.scene_id = scene.scene_id;
  frame.image_id = image_id;
  frame.color = ReadBopColor(FindColorImage(scene, image_id));
  if (scene.has_depth) {
    const fs::path depth_path = scene.dir / "depth" / (BopIdName(image_id) + ".png");
    frame.depth_mm = ReadBopDepth(depth_path, annotations.depth_scale);
    if (frame.depth_mm.size() != frame.color.size()) {
      throw FormatError(Quoted(depth_path) + ": depth is " + std::to_string(frame.depth_mm.cols) +
                        "x" + std::to_string(frame.depth_mm.rows) + " but the colour image is " +
                        std::to_string(frame.color.cols) + "x" + std::to_string(frame.color.rows));
    }
  }
  frame.camera = annotations.camera;
  frame.camera.width = frame.color.cols;
  frame.camera.height = frame.color.rows;
  frame.gt = annotations.gt;
  frame.gt_info = annotations.gt_info;
  return frame;
}

}  // namespace layermod
