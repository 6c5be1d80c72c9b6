// SPDX-License-Identifier: MIT
#pragma once

// Reading datasets in the BOP format (bop.felk.cvut.cz): a split folder (e.g. `test/`) holds one
// folder per scene named by its 6-digit id, each with `scene_camera.json`, `scene_gt.json`,
// `scene_gt_info.json`, `rgb/NNNNNN.png|jpg` and optionally `depth/NNNNNN.png` (16-bit, value x
// depth_scale = mm). Poses are model to camera in mm.

#include <cstdint>
#include <filesystem>
#include <map>
#include <opencv2/core.hpp>
#include <vector>

#include "geometry/camera.h"
#include "geometry/pose.h"

namespace layermod {

// One annotated object instance (an entry of scene_gt.json).
struct BopGroundTruth {
  std::int32_t obj_id = 0;
  Pose cam_from_model;
};

// Its visibility (the entry of scene_gt_info.json at the same index). Boxes are x, y, w, h in
// pixels; BOP writes [-1, -1, -1, -1] for an instance with no visible pixel.
struct BopGtInfo {
  cv::Rect bbox_obj;
  cv::Rect bbox_visib;
  int px_count_all = 0;    // pixels of the object's silhouette in the image
  int px_count_valid = 0;  // of those, pixels with valid depth
  int px_count_visib = 0;  // of those, pixels where the object is not occluded
  double visib_fract = 0.0;
};

// Everything a scene's JSON files say about one image, read once per scene.
struct BopFrameAnnotations {
  // Intrinsics from cam_K; width and height are 0 until the image is read (BOP does not store
  // the image size per frame).
  PinholeCamera camera;
  double depth_scale = 1.0;  // depth PNG value x depth_scale = mm
  std::vector<BopGroundTruth> gt;
  std::vector<BopGtInfo> gt_info;  // same size as gt, or empty when the scene has no gt_info
};

struct BopFrame {
  int scene_id = 0;
  int image_id = 0;
  cv::Mat color;         // BGR8
  cv::Mat depth_mm;      // CV_32F, mm, 0 = invalid; EMPTY when the dataset has no depth
  PinholeCamera camera;  // cam_K with the image size
  std::vector<BopGroundTruth> gt;
  std::vector<BopGtInfo> gt_info;
};

struct BopScene {
  int scene_id = 0;
  std::filesystem::path dir;
  std::vector<int> image_ids;                      // ascending, the images of scene_camera.json
  std::map<int, BopFrameAnnotations> annotations;  // by image id, one per entry of image_ids
  bool has_depth = false;                          // the scene has a depth/ folder
  bool has_gt_info = false;                        // the scene has scene_gt_info.json
};

// The scenes of a split folder (the folder containing 000002/ etc.), ascending by id. A dataset
// root is accepted too: when `split_dir` holds no scene folder but has a `test/` folder, the
// scenes are read from there. Each scene is loaded (LoadBopScene). Throws IoError when the folder
// does not exist and FormatError when it holds no scene.
std::vector<BopScene> ListBopScenes(const std::filesystem::path& split_dir);

// Reads a scene folder's JSON files (scene_camera.json and scene_gt.json are required,
// scene_gt_info.json is optional). The scene id is the folder name. Throws IoError/FormatError
// naming the file and the problem.
BopScene LoadBopScene(const std::filesystem::path& scene_dir);

// Reads one image of a scene: rgb/NNNNNN.png (or .jpg), depth/NNNNNN.png when the scene has
// depth. Throws Error for an id that is not in the scene, IoError for a missing or unreadable
// image, FormatError for an 8-bit depth PNG or a colour/depth size mismatch.
BopFrame LoadBopFrame(const BopScene& scene, int image_id);

// The 6-digit file stem BOP uses for ids ("000042").
std::string BopIdName(int id);
// The file name of a model in a BOP models folder ("obj_000005.ply").
std::string BopModelFileName(int obj_id);

}  // namespace layermod
