// SPDX-License-Identifier: MIT
#include "match/scene_level.h"

#include <tbb/parallel_for.h>

#include <string>

#include "match/spread.h"
#include "util/error.h"

namespace layermod {
namespace {

std::string SizeText(const cv::Size& size) {
  return std::to_string(size.width) + "x" + std::to_string(size.height);
}

cv::Size CommonSize(const std::array<cv::Mat, kModalityCount>& quantized) {
  cv::Size size;
  for (const cv::Mat& image : quantized) {
    if (image.empty()) continue;
    if (image.type() != CV_8UC1) {
      throw Error("quantized scene images must be CV_8UC1 bitmasks, got type " +
                  std::to_string(image.type()));
    }
    if (!size.empty() && image.size() != size) {
      throw Error("quantized scene images of one level differ in size: " + SizeText(size) +
                  " and " + SizeText(image.size()));
    }
    size = image.size();
  }
  return size;
}

}  // namespace

SceneLevel BuildSceneResponses(const std::array<cv::Mat, kModalityCount>& quantized, int spread_px,
                               SimdPath path) {
  if (spread_px < 1 || spread_px > kMaxSpreadPx) {
    throw Error("spread T = " + std::to_string(spread_px) + " is outside 1.." +
                std::to_string(kMaxSpreadPx));
  }
  SceneLevel level;
  level.spread_px = spread_px;
  level.size_px = CommonSize(quantized);
  const SimdPath kernel = ResolveSimdPath(path);
  tbb::parallel_for(0, kModalityCount, [&](int m) {
    if (quantized[m].empty()) return;
    level.present[m] = true;
    level.quantized[m] = quantized[m];
    level.responses[m] = ComputeResponseMaps(SpreadOrientations(quantized[m], spread_px), kernel);
  });
  return level;
}

void LinearizeSceneLevel(SceneLevel& level) {
  if (level.linearized) return;
  tbb::parallel_for(0, kModalityCount * kOrientationCount, [&](int index) {
    const int m = index / kOrientationCount;
    const int label = index % kOrientationCount;
    if (!level.present[m]) return;
    level.memories[m].orientations[label] = Linearize(level.responses[m][label], level.spread_px);
  });
  for (int m = 0; m < kModalityCount; ++m) {
    if (!level.present[m]) continue;
    level.memories[m].spread_px = level.spread_px;
    level.memories[m].grid_size = level.memories[m].orientations[0].grid_size;
  }
  level.linearized = true;
  IndexMemoryRows(level);
}

void IndexMemoryRows(SceneLevel& level) {
  const int spread = level.spread_px;
  level.memory_rows.assign(static_cast<std::size_t>(MemoryRowCount(spread)), nullptr);
  for (int m = 0; m < kModalityCount; ++m) {
    if (!level.present[m]) continue;
    for (int label = 0; label < kOrientationCount; ++label) {
      const LinearMemory& memory = level.memories[m].orientations[label];
      for (int y = 0; y < spread; ++y) {
        for (int x = 0; x < spread; ++x) {
          level.memory_rows[static_cast<std::size_t>(MemoryRowKey(m, label, x, y, spread))] =
              memory.Memory(y, x);
        }
      }
    }
  }
}

SceneLevel BuildSceneLevel(const std::array<cv::Mat, kModalityCount>& quantized, int spread_px,
                           SimdPath path) {
  SceneLevel level = BuildSceneResponses(quantized, spread_px, path);
  LinearizeSceneLevel(level);
  return level;
}

}  // namespace layermod
