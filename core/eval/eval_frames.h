// SPDX-License-Identifier: MIT
#pragma once

// Which images and which objects in them an evaluation looks at.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <vector>

#include "dataset/bop.h"
#include "eval/bop_targets.h"

namespace layermod {

struct FrameSelectionOptions {
  std::optional<int> scene_id;     // only this scene
  std::vector<BopTarget> targets;  // when not empty: only these (scene, image, object) triples
  double min_visib_fract = 0.5;    // instances less visible are not evaluated (scene_gt_info.json)
  int max_frames = 0;              // 0: all
  // Also judge the archives' objects a frame does not show at all: any detection of them is a
  // false one. Frames showing none of the objects are then selected too.
  bool absent_objects = true;

  void Validate() const;  // throws Error naming the bad field
};

// One object to find in a frame and the annotated instances it may be matched against.
struct EvalTarget {
  std::int32_t obj_id = 0;
  std::vector<int> gt_indices;  // into the frame's gt, each visible enough
};

struct EvalFrame {
  std::size_t scene_index = 0;  // into the scene list given to SelectEvalFrames
  int scene_id = 0;
  int image_id = 0;
  std::vector<EvalTarget> targets;  // ascending obj_id
  // Objects of the archives without any annotated instance in the frame (ascending), when
  // FrameSelectionOptions::absent_objects. targets and absent are never both empty.
  std::vector<std::int32_t> absent;
};

// The frames, in scene and image order, that show at least one of `obj_ids` with visibility at
// least min_visib_fract (every instance counts when the scene has no scene_gt_info.json), or,
// with absent_objects, lack one of them altogether. Error when no frame shows one. Throws
// FormatError when a target names a scene or an image the dataset does not have, Error when no
// frame qualifies (naming `dataset_dir`).
std::vector<EvalFrame> SelectEvalFrames(const std::vector<BopScene>& scenes,
                                        const std::set<std::int32_t>& obj_ids,
                                        const FrameSelectionOptions& options,
                                        const std::filesystem::path& dataset_dir);

}  // namespace layermod
