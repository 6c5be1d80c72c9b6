// SPDX-License-Identifier: MIT
#include "match/scene_level.h"

#include <gtest/gtest.h>

#include "match/spread.h"
#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(SceneLevelTest, RunsSpreadResponseAndLinearizeForEachPresentModality) {
  cv::RNG rng(31);
  const cv::Mat colour = test::RandomQuantized({67, 45}, 0.2, rng);
  const SceneLevel level = BuildSceneLevel({colour, cv::Mat()}, 4);
  EXPECT_EQ(level.size_px, cv::Size(67, 45));
  EXPECT_EQ(level.spread_px, 4);
  EXPECT_TRUE(level.HasModality(Modality::kColorGradient));
  EXPECT_FALSE(level.HasModality(Modality::kDepthNormal));
  const cv::Mat spread = test::NaiveSpread(colour, 4);
  for (int label = 0; label < kOrientationCount; ++label) {
    EXPECT_EQ(cv::countNonZero(level.responses[0][label] != test::NaiveResponse(spread, label)), 0);
    EXPECT_TRUE(level.responses[1][label].empty());
  }
  EXPECT_EQ(level.memories[0].grid_size, cv::Size(17, 12));
  EXPECT_EQ(level.memories[1].grid_size, cv::Size());
}

TEST(SceneLevelTest, LinearMemoriesCanBeAddedLater) {
  cv::RNG rng(32);
  const cv::Mat quantized = test::RandomQuantized({50, 40}, 0.2, rng);
  SceneLevel level = BuildSceneResponses({quantized, quantized}, 8);
  EXPECT_FALSE(level.linearized);
  EXPECT_EQ(level.memories[0].grid_size, cv::Size());
  LinearizeSceneLevel(level);
  EXPECT_TRUE(level.linearized);
  const SceneLevel complete = BuildSceneLevel({quantized, quantized}, 8);
  for (int m = 0; m < kModalityCount; ++m) {
    EXPECT_EQ(level.memories[m].grid_size, cv::Size(7, 5));
    EXPECT_EQ(level.memories[m].spread_px, 8);
    for (int label = 0; label < kOrientationCount; ++label) {
      EXPECT_EQ(cv::countNonZero(level.memories[m].orientations[label].memories !=
                                 complete.memories[m].orientations[label].memories),
                0);
    }
  }
}

TEST(SceneLevelTest, NoModalityGivesAnEmptyLevel) {
  const SceneLevel level = BuildSceneLevel({cv::Mat(), cv::Mat()}, 5);
  EXPECT_TRUE(level.size_px.empty());
  EXPECT_FALSE(level.HasModality(Modality::kColorGradient));
}

TEST(SceneLevelTest, RejectsMismatchedSizesTypesAndSpread) {
  const cv::Mat a = cv::Mat::zeros(10, 12, CV_8UC1);
  EXPECT_THROW(BuildSceneLevel({a, cv::Mat::zeros(10, 13, CV_8UC1)}, 4), Error);
  EXPECT_THROW(BuildSceneLevel({a, cv::Mat::zeros(10, 12, CV_16UC1)}, 4), Error);
  EXPECT_THROW(BuildSceneLevel({a, a}, 0), Error);
  EXPECT_NO_THROW(BuildSceneLevel({a, a}, kMaxSpreadPx));
}

}  // namespace
}  // namespace layermod
