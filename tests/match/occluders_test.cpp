// SPDX-License-Identifier: MIT
#include "match/occluders.h"

#include <gtest/gtest.h>

#include <optional>

#include "match/matcher.h"
#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

// Level-0 box -> its counterpart at `level`.
cv::Rect AtLevel(const cv::Rect& box_px, int level) {
  return {box_px.x >> level, box_px.y >> level, box_px.width >> level, box_px.height >> level};
}

// Turns every orientation in `box_px` (and its counterpart at each level) by 180 deg: what a
// template taken from the scene there sees once something else stands in front of it.
void CoverWithAnotherSurface(test::TestScene& scene, const cv::Rect& box_px) {
  for (int level = 0; level < static_cast<int>(scene.quantized.size()); ++level) {
    for (cv::Mat& quantized : scene.quantized[level]) {
      cv::Mat patch = quantized(AtLevel(box_px, level));
      for (auto it = patch.begin<std::uint8_t>(); it != patch.end<std::uint8_t>(); ++it) {
        *it = static_cast<std::uint8_t>((*it << 4) | (*it >> 4));
      }
    }
  }
}

// Per level of `scene`, non-zero inside `box_px`'s counterpart.
std::vector<cv::Mat> Masks(const test::TestScene& scene, const cv::Rect& box_px) {
  std::vector<cv::Mat> masks;
  for (int level = 0; level < static_cast<int>(scene.quantized.size()); ++level) {
    cv::Mat mask = cv::Mat::zeros(scene.quantized[level][0].size(), CV_8UC1);
    mask(AtLevel(box_px, level)).setTo(1);
    masks.push_back(mask);
  }
  return masks;
}

class OccludersTest : public ::testing::Test {
 protected:
  OccludersTest() : rng_(71), scene_(test::RandomScene({320, 240}, 0.1, rng_)) {
    record_ = test::TemplateFromScene(scene_, box_, 63, 3, rng_);
  }

  std::vector<RawMatch> Match(const std::vector<cv::Mat>* masks,
                              const MatchOptions& options) const {
    const PreparedScene prepared(scene_.quantized, scene_.spread_px);
    const std::vector<TemplateRecord> records = {record_};
    std::optional<Occluders> made;
    if (masks != nullptr) made = MakeOccluders(prepared, *masks);
    const TemplateSearch search{records, nullptr, {}, made ? &*made : nullptr};
    return MatchTemplateGroups(prepared, std::span<const TemplateSearch>(&search, 1), options);
  }

  cv::RNG rng_;
  test::TestScene scene_;
  const cv::Rect box_{96, 64, 64, 64};
  TemplateRecord record_;
};

TEST_F(OccludersTest, FeaturesOnAnOccluderAreCountedOutOfTheScore) {
  // The left 24 px of the template's 64 are covered by another surface.
  const cv::Rect cover(box_.x - 16, box_.y - 16, 40, box_.height + 32);
  CoverWithAnotherSurface(scene_, cover);
  MatchOptions options;
  options.threshold_percent = 85.0f;
  EXPECT_TRUE(Match(nullptr, options).empty());

  const std::vector<cv::Mat> masks = Masks(scene_, cover);
  const std::vector<RawMatch> matches = Match(&masks, options);
  ASSERT_FALSE(matches.empty());
  EXPECT_NEAR(matches[0].x, box_.x, 4);  // within the spread plateau
  EXPECT_NEAR(matches[0].y, box_.y, 4);
  EXPECT_GE(matches[0].similarity_percent, 95.0f);  // the visible features match
  const PreparedScene prepared(scene_.quantized, scene_.spread_px);
  const SceneLevel& level0 = prepared.Level(0);
  int sum_of_all = 0;  // what refinement scores at the truth, hidden features included
  for (const Feature& feature : record_.levels[0].features) {
    sum_of_all += level0.responses[ModalityIndex(feature.modality)][feature.label].at<std::uint8_t>(
        box_.y + feature.y, box_.x + feature.x);
  }
  const VisibleScore at_truth =
      ScoreVisibleFeatures(record_.levels[0], level0, masks[0], box_.tl(), sum_of_all);
  EXPECT_EQ(at_truth.features, static_cast<int>(record_.levels[0].features.size()));
  EXPECT_GT(at_truth.hidden, at_truth.features / 5);
  EXPECT_LT(at_truth.hidden, at_truth.features / 2);
  EXPECT_LT(at_truth.sum, sum_of_all);  // the covering surface's responses are taken off
  EXPECT_EQ(at_truth.sum, kMaxFeatureScore * at_truth.Visible());
  EXPECT_GT(matches[0].visible_share, 0.5f);
  EXPECT_LT(matches[0].visible_share, 0.8f);
}

TEST_F(OccludersTest, AMatchNeedsItsShareOfVisibleFeatures) {
  // The left 44 px of 64 are covered: about a third of the features stays visible.
  const cv::Rect cover(box_.x - 16, box_.y - 16, 60, box_.height + 32);
  CoverWithAnotherSurface(scene_, cover);
  const std::vector<cv::Mat> masks = Masks(scene_, cover);
  MatchOptions options;
  options.min_visible_share = 0.5f;
  EXPECT_TRUE(Match(&masks, options).empty());
  options.min_visible_share = 0.2f;
  const std::vector<RawMatch> matches = Match(&masks, options);
  ASSERT_FALSE(matches.empty());
  EXPECT_NEAR(matches[0].x, box_.x, 4);
  EXPECT_NEAR(matches[0].y, box_.y, 4);
  EXPECT_GE(matches[0].visible_share, 0.2f);
  EXPECT_LT(matches[0].visible_share, 0.5f);
}

TEST_F(OccludersTest, EmptyOccluderMasksChangeNothing) {
  const std::vector<cv::Mat> masks = Masks(scene_, cv::Rect());
  MatchOptions options;
  options.threshold_percent = 50.0f;
  const std::vector<RawMatch> plain = Match(nullptr, options);
  ASSERT_FALSE(plain.empty());
  EXPECT_EQ(Match(&masks, options), plain);
}

// The scene templates are ranked on has linear memories of its own (floored at occluders):
// grid features read those, as the features do.
TEST_F(OccludersTest, GridFeaturesReadTheRankedScene) {
  const cv::Rect cover(box_.x - 16, box_.y - 16, 40, box_.height + 32);
  CoverWithAnotherSurface(scene_, cover);
  const PreparedScene prepared(scene_.quantized, scene_.spread_px);
  const Occluders occluders = MakeOccluders(prepared, Masks(scene_, cover));
  const int top = static_cast<int>(record_.levels.size()) - 1;
  const TemplateLevel& level = record_.levels[static_cast<std::size_t>(top)];
  const SceneLevel& ranked = occluders.ranked->LinearizedLevel(top);
  const SceneLevel& plain = prepared.LinearizedLevel(top);
  const cv::Size cells = GridPositionCount(level, ranked);
  std::vector<GridRowSpan> spans;
  for (int row = 0; row < cells.height; ++row) spans.push_back({row, 0, cells.width - 1});
  const auto sums = [&](const SceneLevel& scene, const TemplateLevelSummary& summary) {
    std::vector<std::uint16_t> result;
    ComputeSpanSimilarity(level, scene, summary, spans, result);
    return result;
  };
  const TemplateLevelFacts facts = LevelFacts(level, ranked.spread_px);
  const std::vector<std::uint16_t> ranked_sums =
      sums(ranked, SummarizeTemplateLevel(level, ranked));
  EXPECT_EQ(sums(ranked, SummarizeFacts(facts, ranked)), ranked_sums);
  EXPECT_EQ(sums(plain, SummarizeFacts(facts, plain)),
            sums(plain, SummarizeTemplateLevel(level, plain)));
  EXPECT_NE(ranked_sums, sums(plain, SummarizeTemplateLevel(level, plain)));  // the floors count
}

TEST_F(OccludersTest, MasksOfTheWrongCountSizeOrTypeAreRejected) {
  std::vector<cv::Mat> masks = Masks(scene_, box_);
  masks.pop_back();
  EXPECT_THROW(Match(&masks, {}), Error);
  masks = Masks(scene_, box_);
  masks[1] = cv::Mat::zeros(masks[0].size(), CV_8UC1);
  EXPECT_THROW(Match(&masks, {}), Error);
  masks[1] = cv::Mat::zeros(masks[0].size() / 2, CV_32F);
  EXPECT_THROW(Match(&masks, {}), Error);
}

}  // namespace
}  // namespace layermod
