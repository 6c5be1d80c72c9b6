// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include <layermod/archive.h>
#include <layermod/camera.h>

namespace layermod::api {

// What `layermod train` takes (README "train").
struct TrainOptions {
  std::filesystem::path model;  // mesh file: PLY, STL, OBJ, OFF, glTF, ...
  std::int32_t obj_id = 1;
  std::string name;  // empty: the mesh file's name
  Camera camera;     // the camera the archive will detect with
  // A training profile as JSON (the format of `--profile` files and the studio's saved
  // profiles: depth_min_mm, depth_max_mm, views, features); absent fields keep the defaults.
  // Used when not empty; else profile_file when not empty; else the defaults.
  std::string profile_json;
  std::filesystem::path profile_file;
  std::string units = "mm";  // units of the mesh file: "mm" or "m"
  int threads = 0;           // 0: all hardware threads
  // Heavier meshes are simplified to this many triangles for rendering (0 = never).
  std::size_t max_render_triangles = 12000;
  std::filesystem::path out;  // when not empty, the archive is also written here (atomically)
};

// `done` of `total` templates finished in `stage`. Called from worker threads, never
// concurrently.
using ProgressCallback =
    std::function<void(std::size_t done, std::size_t total, std::string_view stage)>;

// Renders every view at every depth layer of the profile and extracts its LineMOD template,
// in parallel (paper §3.1). Throws IoError / FormatError naming the file for unreadable meshes,
// cameras or profiles, Error for invalid values, and Cancelled (nothing written) when `cancel`
// becomes true; it is checked between templates.
Archive Train(const TrainOptions& options, const ProgressCallback& progress = {},
              const std::atomic<bool>* cancel = nullptr);

}  // namespace layermod::api
