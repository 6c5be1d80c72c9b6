// SPDX-License-Identifier: MIT
#include "dataset/bop_writer.h"

#include <nlohmann/json.hpp>
#include <string>

#include "dataset/bop_images.h"
#include "dataset/bop_json.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson RectJson(const cv::Rect& rect) {
  return OrderedJson::array({rect.x, rect.y, rect.width, rect.height});
}

OrderedJson CameraEntry(const BopFrameAnnotations& frame) {
  const PinholeCamera& camera = frame.camera;
  return {{"cam_K", {camera.fx, 0.0, camera.cx, 0.0, camera.fy, camera.cy, 0.0, 0.0, 1.0}},
          {"depth_scale", frame.depth_scale}};
}

OrderedJson GtEntry(const BopFrameAnnotations& frame) {
  OrderedJson list = OrderedJson::array();
  for (const BopGroundTruth& gt : frame.gt) {
    list.push_back({{"cam_R_m2c", bop_internal::RotationJson(gt.cam_from_model.R)},
                    {"cam_t_m2c", bop_internal::VectorJson(gt.cam_from_model.t)},
                    {"obj_id", gt.obj_id}});
  }
  return list;
}

OrderedJson GtInfoEntry(const BopFrameAnnotations& frame) {
  OrderedJson list = OrderedJson::array();
  for (const BopGtInfo& info : frame.gt_info) {
    list.push_back({{"bbox_obj", RectJson(info.bbox_obj)},
                    {"bbox_visib", RectJson(info.bbox_visib)},
                    {"px_count_all", info.px_count_all},
                    {"px_count_valid", info.px_count_valid},
                    {"px_count_visib", info.px_count_visib},
                    {"visib_fract", info.visib_fract}});
  }
  return list;
}

void CreateFolder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw IoError(bop_internal::Quoted(dir) + ": cannot create the folder (" + ec.message() + ")");
  }
}

}  // namespace

BopSceneWriter::BopSceneWriter(fs::path scene_dir, double depth_scale)
    : dir_(std::move(scene_dir)), depth_scale_(depth_scale) {
  if (!(depth_scale_ > 0.0)) throw Error("BOP writer: depth_scale must be positive");
  CreateFolder(dir_ / "rgb");
}

std::size_t BopSceneWriter::FrameCount() const {
  std::lock_guard lock(mutex_);
  return frames_.size();
}

void BopSceneWriter::CheckFrame(const BopFrame& frame) {
  const std::string name = "image " + std::to_string(frame.image_id);
  if (frame.image_id < 0) throw Error("BOP writer: " + name + ": ids must not be negative");
  if (frame.color.empty() || frame.color.type() != CV_8UC3) {
    throw Error("BOP writer: " + name + ": the colour image must be BGR8");
  }
  if (!frame.depth_mm.empty() &&
      (frame.depth_mm.type() != CV_32F || frame.depth_mm.size() != frame.color.size())) {
    throw Error("BOP writer: " + name + ": depth must be CV_32F of the colour image's size");
  }
  if (!frame.gt_info.empty() && frame.gt_info.size() != frame.gt.size()) {
    throw Error("BOP writer: " + name + ": gt_info must have one entry per gt instance");
  }
  std::lock_guard lock(mutex_);
  if (frames_.count(frame.image_id) != 0) throw Error("BOP writer: " + name + " added twice");
  const int has_depth = frame.depth_mm.empty() ? 0 : 1;
  if (depth_state_ >= 0 && depth_state_ != has_depth) {
    throw Error("BOP writer: " + name + ": every frame of a scene must have depth, or none");
  }
  depth_state_ = has_depth;
  frames_[frame.image_id];  // reserves the id
}

void BopSceneWriter::AddFrame(const BopFrame& frame) {
  CheckFrame(frame);
  const std::string stem = BopIdName(frame.image_id) + ".png";
  try {
    WritePngAtomically(dir_ / "rgb" / stem, frame.color);
    if (!frame.depth_mm.empty()) {
      CreateFolder(dir_ / "depth");
      WritePngAtomically(dir_ / "depth" / stem, EncodeBopDepth(frame.depth_mm, depth_scale_));
    }
  } catch (...) {
    std::lock_guard lock(mutex_);
    frames_.erase(frame.image_id);  // the id may be added again
    throw;
  }
  BopFrameAnnotations annotations;
  annotations.camera = frame.camera;
  annotations.depth_scale = depth_scale_;
  annotations.gt = frame.gt;
  annotations.gt_info = frame.gt_info;
  std::lock_guard lock(mutex_);
  frames_[frame.image_id] = std::move(annotations);
}

void BopSceneWriter::Finish() {
  std::lock_guard lock(mutex_);
  OrderedJson cameras = OrderedJson::object();
  OrderedJson gts = OrderedJson::object();
  OrderedJson gt_infos = OrderedJson::object();
  bool any_gt_info = false;
  for (const auto& [image_id, frame] : frames_) {
    const std::string key = std::to_string(image_id);
    cameras[key] = CameraEntry(frame);
    gts[key] = GtEntry(frame);
    gt_infos[key] = GtInfoEntry(frame);
    any_gt_info = any_gt_info || !frame.gt_info.empty();
  }
  // scene_camera.json last: it is the file that makes a folder a scene.
  if (any_gt_info) {
    WriteFileAtomically(dir_ / "scene_gt_info.json", bop_internal::DumpJson(gt_infos));
  }
  WriteFileAtomically(dir_ / "scene_gt.json", bop_internal::DumpJson(gts));
  WriteFileAtomically(dir_ / "scene_camera.json", bop_internal::DumpJson(cameras));
}

void WriteBopCamera(const fs::path& path, const PinholeCamera& camera, double depth_scale) {
  nlohmann::json json = CameraJson(camera);  // keys sorted, as BOP's own files
  json["depth_scale"] = depth_scale;
  WriteFileAtomically(path, bop_internal::DumpJson(json));
}

}  // namespace layermod
