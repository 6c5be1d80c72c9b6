// SPDX-License-Identifier: MIT
// One pyramid level of a scene, prepared once for matching every template: the quantized
// orientations of each modality, spread, turned into response maps and linearized.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "features/feature.h"
#include "match/linear_memory.h"
#include "match/response_maps.h"
#include "match/simd.h"

namespace layermod {

inline constexpr int kModalityCount = 2;
inline int ModalityIndex(Modality modality) { return static_cast<int>(modality); }

struct SceneLevel {
  cv::Size size_px;   // scene size at this level (0 x 0 when no modality is present)
  int spread_px = 0;  // T
  // Per modality (index ModalityIndex); empty members for an absent modality, e.g. the depth
  // normals of an RGB-only capture.
  std::array<cv::Mat, kModalityCount> quantized;  // the unspread input bitmasks
  std::array<std::array<cv::Mat, kOrientationCount>, kModalityCount> responses;
  // Only needed where templates are scored on the whole grid (their top pyramid level), so they
  // may be added later (LinearizeSceneLevel).
  std::array<LinearMemories, kModalityCount> memories;
  bool linearized = false;
  // Which modalities are present; a plain flag because the matcher asks per feature.
  std::array<bool, kModalityCount> present{};
  // With the linear memories: the first cell of each memory, at MemoryRowKey (IndexMemoryRows);
  // nullptr for an absent modality. Grid scoring reads a feature's memory through it.
  std::vector<const std::uint8_t*> memory_rows;

  bool HasModality(Modality modality) const {
    const int index = ModalityIndex(modality);
    return index < kModalityCount && present[index];
  }
};

// Spread -> response maps for each present modality (index ModalityIndex), without the linear
// memories. Present modalities must be CV_8UC1 of one size; absent ones are empty Mats. Throws
// Error otherwise, or for T outside 1..kMaxSpreadPx.
SceneLevel BuildSceneResponses(const std::array<cv::Mat, kModalityCount>& quantized, int spread_px,
                               SimdPath path = SimdPath::kAuto);

// Adds the linear memories of every present modality (no-op when already linearized).
void LinearizeSceneLevel(SceneLevel& level);

// The index into SceneLevel::memory_rows of the memory that holds orientation `label` of
// modality index `modality` at offset (phase_x, phase_y) within a T x T cell.
constexpr int MemoryRowKey(int modality, int label, int phase_x, int phase_y, int spread_px) {
  return ((modality * kOrientationCount + label) * spread_px + phase_y) * spread_px + phase_x;
}
// The size of SceneLevel::memory_rows for spread `spread_px`: one row per modality, label and
// position within a cell.
constexpr int MemoryRowCount(int spread_px) {
  return MemoryRowKey(kModalityCount, 0, 0, 0, spread_px);
}
// Fills SceneLevel::memory_rows from its linear memories; whatever replaces them calls it again.
void IndexMemoryRows(SceneLevel& level);

// Both: spread -> response maps -> linear memories.
SceneLevel BuildSceneLevel(const std::array<cv::Mat, kModalityCount>& quantized, int spread_px,
                           SimdPath path = SimdPath::kAuto);

}  // namespace layermod
