// SPDX-License-Identifier: MIT
#include "match/similarity.h"

#include <gtest/gtest.h>

#include "match/spread.h"
#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

TemplateLevel RandomTemplate(int feature_count, cv::Size box, cv::RNG& rng) {
  TemplateLevel level;
  level.width = box.width;
  level.height = box.height;
  for (int i = 0; i < feature_count; ++i) {
    level.features.push_back({static_cast<std::int16_t>(rng.uniform(0, box.width)),
                              static_cast<std::int16_t>(rng.uniform(0, box.height)),
                              static_cast<std::uint8_t>(rng.uniform(0, 8)),
                              static_cast<Modality>(rng.uniform(0, 2))});
  }
  return level;
}

struct Scene {
  std::array<cv::Mat, 2> quantized;
  SceneLevel level;
  test::NaiveResponses naive;
};

Scene MakeScene(cv::Size size, int t, double density, cv::RNG& rng, bool with_depth = true) {
  Scene scene;
  scene.quantized = {test::RandomQuantized(size, density, rng),
                     with_depth ? test::RandomQuantized(size, density, rng) : cv::Mat()};
  scene.level = BuildSceneLevel(scene.quantized, t);
  scene.naive = test::NaiveSceneResponses(scene.quantized, t);
  return scene;
}

// Naive valid grid: positions g * T whose box (grown to hold every feature) fits the scene.
cv::Size NaiveGridCount(const TemplateLevel& level, cv::Size scene_size, int t) {
  int width = level.width;
  int height = level.height;
  for (const Feature& f : level.features) {
    width = std::max(width, f.x + 1);
    height = std::max(height, f.y + 1);
  }
  int columns = 0;
  while (columns * t + width <= scene_size.width) ++columns;
  int rows = 0;
  while (rows * t + height <= scene_size.height) ++rows;
  return columns > 0 && rows > 0 ? cv::Size(columns, rows) : cv::Size();
}

void ExpectGridMatchesNaive(const TemplateLevel& level, const Scene& scene,
                            const GridSimilarity& grid, const cv::Mat& mask = cv::Mat()) {
  const int t = scene.level.spread_px;
  ASSERT_EQ(grid.sums.size(), NaiveGridCount(level, scene.level.size_px, t));
  for (int gy = 0; gy < grid.sums.rows; ++gy) {
    for (int gx = 0; gx < grid.sums.cols; ++gx) {
      const bool requested = mask.empty() || mask.at<std::uint8_t>(gy, gx) != 0;
      const int expected = requested ? test::NaiveScore(level, scene.naive, {gx * t, gy * t}) : 0;
      ASSERT_EQ(grid.sums.at<std::uint16_t>(gy, gx), expected) << "cell " << gx << "," << gy;
    }
  }
}

TEST(SimilarityTest, GridAgreesWithNaiveReferenceForEverySpreadAndFeatureCount) {
  cv::RNG rng(41);
  for (const cv::Size size : {cv::Size(97, 61), cv::Size(203, 157)}) {
    for (int t : {1, 2, 3, 4, 5, 7, 8, 16}) {
      const Scene scene = MakeScene(size, t, 0.15, rng);
      for (int count : {1, 20, 63, 64, 126, 200}) {
        const TemplateLevel level = RandomTemplate(count, {31, 22}, rng);
        const GridSimilarity grid = ComputeGridSimilarity(level, scene.level);
        EXPECT_EQ(grid.feature_count, count);
        EXPECT_EQ(grid.spread_px, t);
        ExpectGridMatchesNaive(level, scene, grid);
      }
    }
  }
}

TEST(SimilarityTest, GridAgreesWithNaiveReferenceOnVga) {
  cv::RNG rng(42);
  for (int t : {5, 8}) {
    const Scene scene = MakeScene({640, 480}, t, 0.1, rng);
    const TemplateLevel level = RandomTemplate(126, {90, 70}, rng);
    ExpectGridMatchesNaive(level, scene, ComputeGridSimilarity(level, scene.level));
  }
}

TEST(SimilarityTest, MaskedGridScoresOnlyRequestedCells) {
  cv::RNG rng(43);
  const Scene scene = MakeScene({211, 143}, 5, 0.15, rng);
  for (int count : {40, 150}) {
    const TemplateLevel level = RandomTemplate(count, {25, 25}, rng);
    const cv::Size cells = GridPositionCount(level, scene.level);
    // Sparse cells, whole rows, and neighbouring cells on consecutive rows (runs that merge).
    cv::Mat mask = cv::Mat::zeros(cells, CV_8UC1);
    mask.at<std::uint8_t>(0, 0) = 1;
    mask.row(3).setTo(1);
    mask(cv::Rect(5, 10, 3, 4)).setTo(1);
    mask.at<std::uint8_t>(cells.height - 1, cells.width - 1) = 1;
    ExpectGridMatchesNaive(level, scene, ComputeGridSimilarity(level, scene.level, mask), mask);
    // Only the first rows: the cells after the last run are still read back (as zeros).
    cv::Mat top_rows = cv::Mat::zeros(cells, CV_8UC1);
    top_rows(cv::Rect(2, 0, 4, 2)).setTo(1);
    ExpectGridMatchesNaive(level, scene, ComputeGridSimilarity(level, scene.level, top_rows),
                           top_rows);
    const GridSimilarity none =
        ComputeGridSimilarity(level, scene.level, cv::Mat::zeros(cells, CV_8UC1));
    EXPECT_EQ(cv::countNonZero(none.sums), 0);
    EXPECT_THROW(ComputeGridSimilarity(level, scene.level, cv::Mat::zeros(3, 3, CV_8UC1)), Error);
  }
}

TEST(SimilarityTest, SpansScoreTheirCellsOnly) {
  cv::RNG rng(52);
  const Scene scene = MakeScene({203, 157}, 8, 0.15, rng);
  for (int count : {40, 150}) {
    const TemplateLevel level = RandomTemplate(count, {30, 20}, rng);
    const cv::Size cells = GridPositionCount(level, scene.level);
    // Unsorted, overlapping, partly and wholly outside the grid.
    const std::vector<GridRowSpan> spans = {{5, 3, 6},
                                            {1, -4, 2},
                                            {5, 5, 9},
                                            {cells.height - 1, cells.width - 3, cells.width + 5},
                                            {cells.height + 2, 0, 3},
                                            {2, 7, 4},
                                            {0, 0, 0}};
    cv::Mat expected_cells = cv::Mat::zeros(cells, CV_8UC1);
    expected_cells(cv::Rect(3, 5, 7, 1)).setTo(1);
    expected_cells(cv::Rect(0, 1, 3, 1)).setTo(1);
    expected_cells(cv::Rect(cells.width - 3, cells.height - 1, 3, 1)).setTo(1);
    expected_cells.at<std::uint8_t>(0, 0) = 1;
    ExpectGridMatchesNaive(level, scene, ComputeGridSimilarityInSpans(level, scene.level, spans),
                           expected_cells);
  }
}

TEST(SimilarityTest, SpanSimilarityListsTheSpansCellsInOrder) {
  cv::RNG rng(53);
  const Scene scene = MakeScene({203, 157}, 8, 0.15, rng);
  for (int count : {40, 150}) {
    const TemplateLevel level = RandomTemplate(count, {30, 20}, rng);
    const TemplateLevelSummary summary = SummarizeTemplateLevel(level, scene.level);
    const cv::Size cells = GridPositionCount(level, scene.level);
    // Neighbouring spans on one row and on consecutive rows (their runs merge), a far one.
    const std::vector<GridRowSpan> spans = {
        {0, 0, 0}, {0, 2, 5}, {1, 0, 3}, {4, 6, 6}, {cells.height - 1, 1, cells.width - 1}};
    std::vector<std::uint16_t> sums = {7, 7};  // reused: cleared first
    ComputeSpanSimilarity(level, scene.level, summary, spans, sums);
    std::size_t next = 0;
    for (const GridRowSpan& span : spans) {
      for (int gx = span.first_column; gx <= span.last_column; ++gx) {
        ASSERT_LT(next, sums.size());
        EXPECT_EQ(sums[next++], test::NaiveScore(level, scene.naive, {gx * 8, span.row * 8}))
            << "cell " << gx << "," << span.row;
      }
    }
    EXPECT_EQ(next, sums.size());
    const std::vector<std::vector<GridRowSpan>> refused = {
        {{2, 0, 3}, {1, 0, 3}},  // rows out of order
        {{1, 0, 3}, {1, 3, 5}},  // overlapping
        {{0, 0, cells.width}},   // past the last column
        {{cells.height, 0, 0}},  // past the last row
        {{0, 3, 2}}};            // empty
    for (const std::vector<GridRowSpan>& bad : refused) {
      EXPECT_THROW(ComputeSpanSimilarity(level, scene.level, summary, bad, sums), Error);
    }
  }
}

// Grid features worked out once (LevelFacts with the scene's spread) give the sums the features
// give, for every spread, with both modalities and with colour only; facts for another spread,
// or with a feature too far out for a cell offset, carry none and give the same sums.
TEST(SimilarityTest, GridFeaturesGiveTheSumsTheFeaturesGive) {
  cv::RNG rng(54);
  for (int t = 1; t <= kMaxSpreadPx; t += 3) {
    for (const bool with_depth : {true, false}) {
      const Scene scene = MakeScene({203, 157}, t, 0.15, rng, with_depth);
      const TemplateLevel level = RandomTemplate(90, {40, 30}, rng);
      const cv::Size cells = GridPositionCount(level, scene.level);
      const std::vector<GridRowSpan> spans = {{0, 0, cells.width - 1},
                                              {cells.height - 1, 0, cells.width - 1}};
      const TemplateLevelFacts facts = LevelFacts(level, t);
      ASSERT_EQ(facts.grid_features.size(), level.features.size());
      const TemplateLevelSummary summary = SummarizeFacts(facts, scene.level);
      ASSERT_EQ(summary.grid_features.size(), level.features.size());
      std::vector<std::uint16_t> from_grid;
      ComputeSpanSimilarity(level, scene.level, summary, spans, from_grid);
      std::vector<std::uint16_t> from_features;
      ComputeSpanSimilarity(level, scene.level, SummarizeTemplateLevel(level, scene.level), spans,
                            from_features);
      EXPECT_EQ(from_grid, from_features) << "T " << t << (with_depth ? "" : ", colour only");
      std::size_t next = 0;
      for (int gx = 0; gx < cells.width; ++gx) {
        ASSERT_EQ(from_grid[next++], test::NaiveScore(level, scene.naive, {gx * t, 0}));
      }
      const TemplateLevelFacts other_spread = LevelFacts(level, t % kMaxSpreadPx + 1);
      EXPECT_TRUE(SummarizeFacts(other_spread, scene.level).grid_features.empty());
    }
  }
  TemplateLevel far = RandomTemplate(10, {20, 20}, rng);
  far.features[3].x = 256;  // cell 256 at T = 1
  EXPECT_TRUE(LevelFacts(far, 1).grid_features.empty());
  EXPECT_EQ(LevelFacts(far, 2).grid_features.size(), far.features.size());
  EXPECT_THROW(LevelFacts(far, kMaxSpreadPx + 1), Error);
}

TEST(SimilarityTest, LocalWindowAgreesWithNaiveReferenceAndIsClipped) {
  cv::RNG rng(44);
  for (int t : {1, 5, 8}) {
    const Scene scene = MakeScene({97, 61}, t, 0.15, rng);
    for (int count : {30, 126}) {
      const TemplateLevel level = RandomTemplate(count, {20, 15}, rng);
      for (const cv::Rect window : {cv::Rect(10, 7, 12, 12), cv::Rect(-5, -3, 11, 9),
                                    cv::Rect(70, 40, 30, 30), cv::Rect(0, 0, 78, 47)}) {
        const LocalSimilarity local = ComputeLocalSimilarity(level, scene.level, window);
        EXPECT_EQ(local.window_px, window & cv::Rect(0, 0, 97 - 20 + 1, 61 - 15 + 1));
        ASSERT_EQ(local.sums.size(), local.window_px.size());
        for (int r = 0; r < local.sums.rows; ++r) {
          for (int c = 0; c < local.sums.cols; ++c) {
            const cv::Point p = local.window_px.tl() + cv::Point(c, r);
            ASSERT_EQ(local.sums.at<std::uint16_t>(r, c), test::NaiveScore(level, scene.naive, p))
                << "T=" << t << " window " << window << " at " << p;
          }
        }
      }
      EXPECT_TRUE(ComputeLocalSimilarity(level, scene.level, {200, 200, 5, 5}).sums.empty());
    }
  }
}

TEST(SimilarityTest, SimdPathsAndAccumulatorsAgree) {
  cv::RNG rng(45);
  const Scene scene = MakeScene({157, 103}, 5, 0.2, rng);
  for (int count : {10, 63, 100, 200}) {
    const TemplateLevel level = RandomTemplate(count, {30, 30}, rng);
    const GridSimilarity reference = ComputeGridSimilarity(
        level, scene.level, cv::Mat(), {Accumulator::k16Bit, SimdPath::kScalar});
    const LocalSimilarity local_reference = ComputeLocalSimilarity(
        level, scene.level, {3, 4, 40, 17}, {Accumulator::k16Bit, SimdPath::kScalar});
    std::vector<Accumulator> accumulators = {Accumulator::kAuto, Accumulator::k16Bit};
    if (count <= kMax8BitFeatures) accumulators.push_back(Accumulator::k8Bit);
    for (SimdPath path : SupportedSimdPaths()) {
      for (Accumulator accumulator : accumulators) {
        const SimilarityOptions options{accumulator, path};
        const GridSimilarity grid = ComputeGridSimilarity(level, scene.level, cv::Mat(), options);
        EXPECT_EQ(cv::countNonZero(grid.sums != reference.sums), 0)
            << count << " features, " << SimdPathName(path);
        const LocalSimilarity local =
            ComputeLocalSimilarity(level, scene.level, {3, 4, 40, 17}, options);
        EXPECT_EQ(cv::countNonZero(local.sums != local_reference.sums), 0);
      }
    }
    if (count > kMax8BitFeatures) {
      EXPECT_THROW(ComputeGridSimilarity(level, scene.level, cv::Mat(), {Accumulator::k8Bit}),
                   Error);
    }
  }
}

TEST(SimilarityTest, SixteenBitPathScoresTwoHundredMatchingFeaturesWithoutOverflow) {
  cv::RNG rng(46);
  // Dense scene so that 200 labelled pixels of one modality fit in the patch.
  const Scene scene = MakeScene({120, 90}, 4, 0.5, rng);
  const cv::Rect box(40, 32, 40, 30);
  TemplateLevel level = test::TemplateFromPatch(scene.quantized, box, 100, 0, rng);
  ASSERT_EQ(level.features.size(), 200u);
  const LocalSimilarity local =
      ComputeLocalSimilarity(level, scene.level, {box.tl(), box.tl() + cv::Point(1, 1)});
  ASSERT_EQ(local.sums.size(), cv::Size(1, 1));
  EXPECT_EQ(local.sums.at<std::uint16_t>(0, 0), 200 * kMaxFeatureScore);
  EXPECT_FLOAT_EQ(SimilarityPercent(local.sums.at<std::uint16_t>(0, 0), local.feature_count),
                  100.0f);
  // The grid cell holding the box's top-left (box.x, box.y are multiples of T) scores fully.
  const GridSimilarity grid = ComputeGridSimilarity(level, scene.level);
  EXPECT_EQ(grid.sums.at<std::uint16_t>(box.y / 4, box.x / 4), 800);
  EXPECT_EQ(ExactAlignmentScore(level, scene.level, box.tl()), 800);
}

TEST(SimilarityTest, TemplateFromPatchScoresFullyOverItsSpreadPlateau) {
  cv::RNG rng(47);
  const Scene scene = MakeScene({90, 70}, 5, 0.15, rng);
  const cv::Rect box(33, 21, 24, 18);
  const TemplateLevel level = test::TemplateFromPatch(scene.quantized, box, 30, 0, rng);
  const LocalSimilarity local =
      ComputeLocalSimilarity(level, scene.level, {box.x - 4, box.y - 4, 5, 5});
  const int full = static_cast<int>(level.features.size()) * kMaxFeatureScore;
  EXPECT_EQ(cv::countNonZero(local.sums == full), 25);  // every p in (p0 - T, p0]
  // Only the true position aligns exactly.
  EXPECT_EQ(ExactAlignmentScore(level, scene.level, box.tl()), full);
  EXPECT_LT(ExactAlignmentScore(level, scene.level, box.tl() - cv::Point(1, 0)), full);
}

TEST(SimilarityTest, AbsentModalityFeaturesAreLeftOut) {
  cv::RNG rng(48);
  const Scene rgb_only = MakeScene({80, 60}, 4, 0.2, rng, false);
  TemplateLevel level = RandomTemplate(50, {20, 20}, rng);
  int colour = 0;
  for (const Feature& f : level.features) colour += f.modality == Modality::kColorGradient;
  EXPECT_EQ(UsableFeatureCount(level, rgb_only.level), colour);
  const GridSimilarity grid = ComputeGridSimilarity(level, rgb_only.level);
  EXPECT_EQ(grid.feature_count, colour);
  ExpectGridMatchesNaive(level, rgb_only, grid);
}

TEST(SimilarityTest, GridNeedsLinearMemories) {
  cv::RNG rng(51);
  const SceneLevel responses_only =
      BuildSceneResponses({test::RandomQuantized({40, 30}, 0.2, rng), cv::Mat()}, 4);
  const TemplateLevel level = RandomTemplate(10, {10, 10}, rng);
  EXPECT_THROW(ComputeGridSimilarity(level, responses_only), Error);
  EXPECT_NO_THROW(ComputeLocalSimilarity(level, responses_only, {0, 0, 4, 4}));
}

TEST(SimilarityTest, TemplateLargerThanSceneHasNoPositions) {
  cv::RNG rng(49);
  const Scene scene = MakeScene({30, 20}, 4, 0.2, rng);
  TemplateLevel level = RandomTemplate(10, {31, 10}, rng);
  EXPECT_TRUE(ValidPositions(level, scene.level.size_px).empty());
  EXPECT_TRUE(ComputeGridSimilarity(level, scene.level).sums.empty());
  EXPECT_TRUE(ComputeLocalSimilarity(level, scene.level, {0, 0, 5, 5}).window_px.empty());
  EXPECT_THROW(ExactAlignmentScore(level, scene.level, {0, 0}), Error);
}

TEST(SimilarityTest, FeaturesOutsideTheBoxGrowTheExtent) {
  TemplateLevel level;
  level.width = 10;
  level.height = 5;
  level.features = {{12, 3, 0, Modality::kColorGradient}, {1, 7, 2, Modality::kDepthNormal}};
  EXPECT_EQ(TemplateExtent(level), cv::Size(13, 8));
  EXPECT_EQ(ValidPositions(level, {20, 20}), cv::Rect(0, 0, 8, 13));
}

TEST(SimilarityTest, InvalidFeaturesThrow) {
  const Scene scene = [] {
    cv::RNG rng(50);
    return MakeScene({40, 40}, 4, 0.2, rng);
  }();
  TemplateLevel level;
  level.width = level.height = 5;
  level.features = {{1, 1, 8, Modality::kColorGradient}};
  EXPECT_THROW(ComputeGridSimilarity(level, scene.level), Error);
  level.features = {{-1, 1, 3, Modality::kColorGradient}};
  EXPECT_THROW(ComputeLocalSimilarity(level, scene.level, {0, 0, 3, 3}), Error);
  level.features = {{1, 1, 3, static_cast<Modality>(2)}};
  EXPECT_THROW(CheckTemplateLevel(level), Error);
}

TEST(SimilarityTest, PercentIsRelativeToTheMaximumScore) {
  EXPECT_FLOAT_EQ(SimilarityPercent(0, 10), 0.0f);
  EXPECT_FLOAT_EQ(SimilarityPercent(20, 10), 50.0f);
  EXPECT_FLOAT_EQ(SimilarityPercent(40, 10), 100.0f);
  EXPECT_FLOAT_EQ(SimilarityPercent(5, 0), 0.0f);
}

}  // namespace
}  // namespace layermod
