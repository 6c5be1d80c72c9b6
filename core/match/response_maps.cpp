// SPDX-License-Identifier: MIT
#include "match/response_maps.h"

#include <algorithm>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

struct NibbleTables {
  // low[l][m]: best similarity of orientation l with the bits of m as labels 0..3;
  // high[l][m]: the same with the bits of m as labels 4..7.
  std::array<std::array<std::uint8_t, 16>, kOrientationCount> low{};
  std::array<std::array<std::uint8_t, 16>, kOrientationCount> high{};
};

constexpr int ConstexprOrientationSimilarity(int label, int scene_label) {
  const int difference =
      (label > scene_label ? label - scene_label : scene_label - label) % kOrientationCount;
  const int distance = std::min(difference, kOrientationCount - difference);
  if (distance == 0) return kMaxFeatureScore;
  return distance == 1 ? 1 : 0;
}

constexpr NibbleTables MakeNibbleTables() {
  NibbleTables tables;
  for (int label = 0; label < kOrientationCount; ++label) {
    for (int nibble = 0; nibble < 16; ++nibble) {
      int low = 0;
      int high = 0;
      for (int bit = 0; bit < 4; ++bit) {
        if ((nibble & (1 << bit)) == 0) continue;
        low = std::max(low, ConstexprOrientationSimilarity(label, bit));
        high = std::max(high, ConstexprOrientationSimilarity(label, bit + 4));
      }
      tables.low[label][nibble] = static_cast<std::uint8_t>(low);
      tables.high[label][nibble] = static_cast<std::uint8_t>(high);
    }
  }
  return tables;
}

// Built by the compiler: the similarity kernels read them for every pixel.
constexpr NibbleTables kTables = MakeNibbleTables();

// Whole-byte rows of the nibble tables: refinement looks up one label against many pixels.
using SimilarityRows = std::array<std::array<std::uint8_t, 256>, kOrientationCount>;

constexpr SimilarityRows MakeSimilarityRows() {
  SimilarityRows rows{};
  for (int label = 0; label < kOrientationCount; ++label) {
    for (int bitmask = 0; bitmask < 256; ++bitmask) {
      rows[label][bitmask] =
          std::max(kTables.low[label][bitmask & 15], kTables.high[label][bitmask >> 4]);
    }
  }
  return rows;
}

constexpr SimilarityRows kSimilarityRows = MakeSimilarityRows();

}  // namespace

const std::uint8_t* BitmaskSimilarityRow(int label) { return kSimilarityRows[label].data(); }

int OrientationSimilarity(int label, int scene_label) {
  return ConstexprOrientationSimilarity(label, scene_label);
}

int BitmaskSimilarity(int label, std::uint8_t bitmask) { return kSimilarityRows[label][bitmask]; }

std::array<cv::Mat, kOrientationCount> ComputeResponseMaps(const cv::Mat& spread, SimdPath path) {
  if (!spread.empty() && spread.type() != CV_8UC1) {
    throw Error("spread orientations must be CV_8UC1 bitmasks, got type " +
                std::to_string(spread.type()));
  }
  const SimdPath kernel = ResolveSimdPath(path);
  const NibbleTables& tables = kTables;
  std::array<cv::Mat, kOrientationCount> maps;
  if (spread.empty()) return maps;
  for (int label = 0; label < kOrientationCount; ++label) {
    // The slack columns are 0 so block reads past a row's end add nothing surprising; the
    // lookup below writes every other byte.
    cv::Mat storage(spread.rows, spread.cols + kSimdBlock, CV_8UC1);
    storage.colRange(spread.cols, storage.cols).setTo(0);
    maps[label] = storage.colRange(0, spread.cols);
    for (int y = 0; y < spread.rows; ++y) {
      LookupNibbleMax(spread.ptr<std::uint8_t>(y), maps[label].ptr<std::uint8_t>(y), spread.cols,
                      tables.low[label].data(), tables.high[label].data(), kernel);
    }
  }
  return maps;
}

}  // namespace layermod
