// SPDX-License-Identifier: MIT
#pragma once

// Writing BOP scenes (the synthetic scene generator's output).

#include <filesystem>
#include <map>
#include <mutex>

#include "dataset/bop.h"

namespace layermod {

// Writes one scene folder: images as frames arrive, the JSON files that make the scene readable
// only in Finish(). A scene whose writer never finished (cancelled or failed run) therefore has
// no scene_camera.json / scene_gt.json and is refused by LoadBopScene.
class BopSceneWriter {
 public:
  // Creates `scene_dir` and its rgb/ folder. Depth is stored as 16-bit PNG in units of
  // `depth_scale` mm (1.0: millimetres). Throws Error for a non-positive scale, IoError when the
  // folder cannot be created.
  explicit BopSceneWriter(std::filesystem::path scene_dir, double depth_scale = 1.0);

  // Writes rgb/NNNNNN.png and, when frame.depth_mm is not empty, depth/NNNNNN.png (each
  // atomically), and keeps the camera and annotations. Thread-safe: frames may be added from
  // several threads in any order. Throws Error for a duplicate image id, a colour image that is
  // not BGR8, a depth map that is not CV_32F of the colour size, gt_info not matching gt, a mix
  // of frames with and without depth; IoError when writing fails.
  void AddFrame(const BopFrame& frame);

  // Writes scene_gt_info.json, scene_gt.json and scene_camera.json atomically, ordered by image
  // id. Throws IoError.
  void Finish();

  const std::filesystem::path& Dir() const { return dir_; }
  std::size_t FrameCount() const;

 private:
  void CheckFrame(const BopFrame& frame);

  std::filesystem::path dir_;
  double depth_scale_;
  mutable std::mutex mutex_;
  std::map<int, BopFrameAnnotations> frames_;
  int depth_state_ = -1;  // -1 unknown, 0 frames without depth, 1 frames with depth
};

// Writes a BOP camera.json (fx fy cx cy width height depth_scale) atomically. Throws IoError.
void WriteBopCamera(const std::filesystem::path& path, const PinholeCamera& camera,
                    double depth_scale = 1.0);

}  // namespace layermod
