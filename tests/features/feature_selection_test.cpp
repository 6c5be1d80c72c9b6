// SPDX-License-Identifier: MIT
#include "features/feature_selection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <random>

#include "util/error.h"

namespace layermod {
namespace {

std::vector<FeatureCandidate> DenseSquare(int side, float score) {
  std::vector<FeatureCandidate> candidates;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      candidates.push_back({x + 10, y + 20, static_cast<std::uint8_t>((x + y) % 8), score});
    }
  }
  return candidates;
}

std::vector<FeatureCandidate> RandomCandidates(int count, int side, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> score(0.0f, 100.0f);
  std::vector<FeatureCandidate> candidates;
  const int area = side * side;
  std::vector<bool> used(area, false);
  while (static_cast<int>(candidates.size()) < count) {
    const int index = static_cast<int>(rng() % area);
    if (used[index]) continue;
    used[index] = true;
    candidates.push_back(
        {index % side, index / side, static_cast<std::uint8_t>(rng() % 8), score(rng)});
  }
  return candidates;
}

double MinSpacing(const std::vector<Feature>& features) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < features.size(); ++i) {
    for (size_t j = i + 1; j < features.size(); ++j) {
      best =
          std::min(best, std::hypot(features[i].x - features[j].x, features[i].y - features[j].y));
    }
  }
  return best;
}

TEST(SelectScatteredFeaturesTest, KeepsExactlyTheRequestedCount) {
  for (int count : {1, 8, 63, 150, 400}) {
    const auto features =
        SelectScatteredFeatures(RandomCandidates(1000, 100, 7), count, Modality::kColorGradient);
    EXPECT_EQ(static_cast<int>(features.size()), count);
  }
}

TEST(SelectScatteredFeaturesTest, SpreadsFeaturesOverTheCandidates) {
  // Equal scores on a dense 100 x 100 square: 25 features form a grid 20 px apart.
  const auto features = SelectScatteredFeatures(DenseSquare(100, 1.0f), 25, Modality::kDepthNormal);
  ASSERT_EQ(features.size(), 25u);
  EXPECT_GE(MinSpacing(features), 19.9);
  for (const Feature& f : features) EXPECT_EQ(f.modality, Modality::kDepthNormal);

  // Random candidates: spacing stays near the grid spacing of the area, far above what the 63
  // best-scored candidates alone would give.
  auto candidates = RandomCandidates(2000, 120, 3);
  const auto scattered = SelectScatteredFeatures(candidates, 63, Modality::kColorGradient);
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.score > b.score; });
  std::vector<Feature> best_only;
  best_only.reserve(63);
  for (int i = 0; i < 63; ++i) {
    best_only.push_back({static_cast<std::int16_t>(candidates[i].x),
                         static_cast<std::int16_t>(candidates[i].y), 0, Modality::kColorGradient});
  }
  EXPECT_GE(MinSpacing(scattered), 8.0);
  EXPECT_GT(MinSpacing(scattered), 2.0 * MinSpacing(best_only));
}

TEST(SelectScatteredFeaturesTest, BestCandidateComesFirst) {
  auto candidates = RandomCandidates(500, 60, 11);
  candidates[123].score = 1000.0f;
  const auto features = SelectScatteredFeatures(candidates, 20, Modality::kColorGradient);
  ASSERT_FALSE(features.empty());
  EXPECT_EQ(features[0].x, candidates[123].x);
  EXPECT_EQ(features[0].y, candidates[123].y);
  EXPECT_EQ(features[0].label, candidates[123].label);
}

TEST(SelectScatteredFeaturesTest, IsDeterministicWhateverTheInputOrder) {
  auto candidates = DenseSquare(50, 3.0f);  // all ties: order decided by position
  const auto reference = SelectScatteredFeatures(candidates, 40, Modality::kColorGradient);
  std::mt19937 rng(5);
  for (int trial = 0; trial < 3; ++trial) {
    std::shuffle(candidates.begin(), candidates.end(), rng);
    EXPECT_EQ(SelectScatteredFeatures(candidates, 40, Modality::kColorGradient), reference);
  }
}

TEST(SelectScatteredFeaturesTest, FewerCandidatesThanRequestedAreAllKept) {
  const std::vector<FeatureCandidate> candidates = {
      {5, 5, 1, 2.0f}, {6, 5, 2, 9.0f}, {30, 7, 3, 5.0f}};
  const auto features = SelectScatteredFeatures(candidates, 63, Modality::kColorGradient);
  ASSERT_EQ(features.size(), 3u);
  EXPECT_EQ(features[0], (Feature{6, 5, 2, Modality::kColorGradient}));  // best score first
  EXPECT_EQ(features[1], (Feature{30, 7, 3, Modality::kColorGradient}));
  EXPECT_EQ(features[2], (Feature{5, 5, 1, Modality::kColorGradient}));
}

TEST(SelectScatteredFeaturesTest, EmptyInputsAndBadCandidates) {
  EXPECT_TRUE(SelectScatteredFeatures({}, 10, Modality::kColorGradient).empty());
  EXPECT_TRUE(SelectScatteredFeatures(DenseSquare(5, 1.0f), 0, Modality::kColorGradient).empty());
  EXPECT_THROW(SelectScatteredFeatures({{40000, 0, 0, 1.0f}}, 1, Modality::kColorGradient), Error);
  EXPECT_THROW(SelectScatteredFeatures({{0, 0, 8, 1.0f}}, 1, Modality::kColorGradient), Error);
}

TEST(SelectScatteredFeaturesTest, DuplicatePositionsStillFillTheCount) {
  std::vector<FeatureCandidate> candidates(20, FeatureCandidate{3, 4, 1, 1.0f});
  EXPECT_EQ(SelectScatteredFeatures(candidates, 10, Modality::kColorGradient).size(), 10u);
}

}  // namespace
}  // namespace layermod
