// SPDX-License-Identifier: MIT
// A tiny BOP scene written by the tests themselves, and helpers to break it.
#pragma once

#include <filesystem>
#include <string>

namespace layermod::test {

void WriteText(const std::filesystem::path& path, const std::string& text);

// scene_camera.json text for the given image ids (cam_K of a 64x48 camera, depth_scale 1).
std::string SceneCameraJson(const std::string& ids_csv, const std::string& cam_k = "",
                            const std::string& depth_scale = "1.0");
// scene_gt.json with one instance of obj 7 per image (`r`/`t` replace the pose arrays).
std::string SceneGtJson(const std::string& ids_csv, const std::string& r = "",
                        const std::string& t = "");
std::string SceneGtInfoJson(const std::string& ids_csv);

// Writes `root`/test/000002/ with images 0 and 5: JSON files, rgb/ 64x48 PNGs, and 16-bit depth
// PNGs whose value at (x, y) is 500 + x + y (mm). Returns the scene folder.
std::filesystem::path WriteTinyScene(const std::filesystem::path& root);

}  // namespace layermod::test
