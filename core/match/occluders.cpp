// SPDX-License-Identifier: MIT
#include "match/occluders.h"

#include <string>

#include <opencv2/core.hpp>

#include "match/linear_memory.h"
#include "util/error.h"

namespace layermod {
namespace {

void CheckMask(const cv::Mat& mask, const SceneLevel& level) {
  if (mask.type() != CV_8UC1 || mask.size() != level.size_px) {
    throw Error("occluder mask must be CV_8UC1 of the scene level's size");
  }
}

// `source` (linearized) whose linear memories score at least `hidden_credit` at the pixels of
// `mask` for every feature; the rest, response maps included, shared with `source`.
SceneLevel WithHiddenPixels(const SceneLevel& source, const cv::Mat& mask, int hidden_credit) {
  SceneLevel level = source;
  cv::Mat credit = cv::Mat::zeros(mask.size(), CV_8UC1);
  credit.setTo(hidden_credit, mask);
  const LinearMemory floors = Linearize(credit, source.spread_px);
  for (int m = 0; m < kModalityCount; ++m) {
    if (!source.present[m]) continue;
    for (LinearMemory& memory : level.memories[m].orientations) {
      memory = ResponseAtLeast(memory, floors);
    }
  }
  IndexMemoryRows(level);  // the copy's table still points into `source`
  return level;
}

}  // namespace

Occluders MakeOccluders(const PreparedScene& scene, std::vector<cv::Mat> masks, int hidden_credit,
                        const cv::Rect& clear_px) {
  if (hidden_credit < 0 || hidden_credit > kMaxFeatureScore) {
    throw Error("occluders: a hidden feature's credit must lie in 0.." +
                std::to_string(kMaxFeatureScore));
  }
  if (static_cast<int>(masks.size()) != scene.LevelCount()) {
    throw Error("occluder masks: " + std::to_string(masks.size()) + " for a scene of " +
                std::to_string(scene.LevelCount()) + " levels");
  }
  std::vector<SceneLevel> ranked;
  for (std::size_t level = 0; level < masks.size(); ++level) {
    const SceneLevel& source = scene.Level(static_cast<int>(level));
    CheckMask(masks[level], source);
    if (level == 0) {
      ranked.push_back(source);
    } else {
      ranked.push_back(WithHiddenPixels(scene.LinearizedLevel(static_cast<int>(level)),
                                        masks[level], hidden_credit));
    }
  }
  return {std::move(masks), hidden_credit, clear_px,
          std::make_shared<const PreparedScene>(std::move(ranked))};
}

Occluders WithLevelZeroMask(const Occluders& shared, cv::Mat level0_mask) {
  if (shared.masks.empty() || level0_mask.type() != CV_8UC1 ||
      level0_mask.size() != shared.masks.front().size()) {
    throw Error("occluder mask must be CV_8UC1 of the scene level's size");
  }
  Occluders occluders = shared;
  occluders.masks.front() = std::move(level0_mask);
  occluders.clear_px = cv::Rect();  // not known for the new mask
  return occluders;
}

VisibleScore ScoreVisibleFeatures(const TemplateLevel& level, const SceneLevel& scene,
                                  const cv::Mat& occluders, const cv::Point& top_left_px,
                                  int sum_of_all) {
  CheckMask(occluders, scene);
  const cv::Rect inside(cv::Point(0, 0), scene.size_px);
  VisibleScore score{0, 0, sum_of_all};
  for (const Feature& feature : level.features) {
    if (!scene.HasModality(feature.modality)) continue;
    ++score.features;
    const int x = top_left_px.x + feature.x;
    const int y = top_left_px.y + feature.y;
    if (!inside.contains({x, y}) || occluders.ptr<std::uint8_t>(y)[x] == 0) continue;
    ++score.hidden;
    const cv::Mat& response = scene.responses[ModalityIndex(feature.modality)][feature.label];
    score.sum -= response.ptr<std::uint8_t>(y)[x];
  }
  return score;
}

}  // namespace layermod
