// SPDX-License-Identifier: MIT
#pragma once

// BOP's target lists (test_targets_bop19.json): which objects of which images are evaluated.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace layermod {

struct BopTarget {
  int scene_id = 0;
  int image_id = 0;
  std::int32_t obj_id = 0;
  int instance_count = 1;
};

// Reads a JSON array of {scene_id, im_id, obj_id, inst_count}. Throws IoError / FormatError
// naming the file and the entry.
std::vector<BopTarget> LoadBopTargets(const std::filesystem::path& path);

}  // namespace layermod
