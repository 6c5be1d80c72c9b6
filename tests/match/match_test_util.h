// SPDX-License-Identifier: MIT
// Naive reference implementations (plain loops over pixels) and random test scenes for the
// matching stage's tests. Deliberately written without the production code's tricks.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "features/feature.h"
#include "templates/template_record.h"

namespace layermod::test {

// Each pixel 0, or with probability `density` one bit 1 << label, label uniform in 0..7.
cv::Mat RandomQuantized(const cv::Size& size, double density, cv::RNG& rng);
// Arbitrary bytes (several bits per pixel, as after spreading).
cv::Mat RandomBytes(const cv::Size& size, cv::RNG& rng);

// OR over (x + dx, y + dy), 0 <= dx, dy < T, inside the image.
cv::Mat NaiveSpread(const cv::Mat& quantized, int spread_px);
// 4 same bin, 1 adjacent bin (circular), 0 otherwise: written out as a table.
int NaiveOrientationSimilarity(int label, int scene_label);
// Per pixel: best NaiveOrientationSimilarity of `label` over the set bits of `spread`.
cv::Mat NaiveResponse(const cv::Mat& spread, int label);

// Naive responses of every modality and orientation; absent modality -> empty maps.
using NaiveResponses = std::array<std::array<cv::Mat, 8>, 2>;
NaiveResponses NaiveSceneResponses(const std::array<cv::Mat, 2>& quantized, int spread_px);
// Score of `level` at top-left `position` (features of absent modalities skipped).
int NaiveScore(const TemplateLevel& level, const NaiveResponses& responses,
               const cv::Point& position);

// Up to `per_modality` features per modality taken from the labelled pixels of `box` (level
// pixels), relative to its top-left; width/height = box size.
TemplateLevel TemplateFromPatch(const std::array<cv::Mat, 2>& quantized, const cv::Rect& box,
                                int per_modality, int pyramid_level, cv::RNG& rng);

// A two-level random scene (level 1 is (W + 1) / 2 x (H + 1) / 2), both modalities.
struct TestScene {
  std::vector<std::array<cv::Mat, 2>> quantized;
  std::vector<int> spread_px = {5, 8};
};
TestScene RandomScene(const cv::Size& size, double density, cv::RNG& rng);

// A template of every level of `scene`, taken from the scene itself at the level-0 box `box`
// (level k: box top-left >> k, size >> k), so it matches there exactly.
TemplateRecord TemplateFromScene(const TestScene& scene, const cv::Rect& box, int per_modality,
                                 std::uint32_t id, cv::RNG& rng);

// Copies the content under the level-0 box `box` (and its counterpart at every level) so that its
// top-left lands on `to`.
void CopyPatch(TestScene& scene, const cv::Rect& box, const cv::Point& to);

}  // namespace layermod::test
