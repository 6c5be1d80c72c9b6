// SPDX-License-Identifier: MIT
#include "match/matcher.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <set>

#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kDensity = 0.1;

PreparedScene Prepare(const test::TestScene& scene) {
  return PreparedScene(scene.quantized, scene.spread_px);
}

cv::Point Centre(const cv::Rect& box) {
  return box.tl() + cv::Point(box.width / 2, box.height / 2);
}

std::vector<RawMatch> Match(const PreparedScene& scene, const std::vector<TemplateRecord>& records,
                            const MatchOptions& options = {},
                            const std::vector<cv::Point>* points = nullptr, int radius = 0) {
  return MatchTemplates(scene, records, options, points, radius);
}

TEST(MatcherTest, FindsATemplateAtItsExactPositionInteriorAndAtBorders) {
  cv::RNG rng(61);
  for (const cv::Size size : {cv::Size(640, 480), cv::Size(203, 157)}) {
    test::TestScene scene = test::RandomScene(size, kDensity, rng);
    const PreparedScene prepared = Prepare(scene);
    const cv::Size box_size(61, 47);
    for (const cv::Point tl :
         {cv::Point(71, 43), cv::Point(0, 0),
          cv::Point(size.width - box_size.width, size.height - box_size.height),
          cv::Point(size.width - box_size.width, 0)}) {
      const std::vector<TemplateRecord> records = {
          test::TemplateFromScene(scene, {tl, box_size}, 63, 7, rng)};
      const std::vector<RawMatch> matches = Match(prepared, records);
      ASSERT_FALSE(matches.empty()) << size << " at " << tl;
      EXPECT_EQ(matches[0].x, tl.x) << size;
      EXPECT_EQ(matches[0].y, tl.y) << size;
      EXPECT_FLOAT_EQ(matches[0].similarity_percent, 100.0f);
      EXPECT_EQ(matches[0].template_id, 7u);
    }
  }
}

TEST(MatcherTest, CandidatePointsRestrictTheSearchAroundTheTemplateAnchor) {
  cv::RNG rng(64);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  const cv::Rect box(101, 67, 61, 47);
  TemplateRecord record = test::TemplateFromScene(scene, box, 63, 4, rng);
  record.centre_offset_px = cv::Point2f(12.0f, 35.0f);  // an anchor off the box centre
  const std::vector<cv::Point> at_anchor = {box.tl() + cv::Point(12, 35)};
  const auto found = Match(prepared, {record}, {}, &at_anchor, 3);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(cv::Point(found[0].x, found[0].y), box.tl());
  // The box centre is about 21 px from the anchor: outside a 3 px radius, inside a 30 px one.
  const std::vector<cv::Point> at_centre = {Centre(box)};
  EXPECT_TRUE(Match(prepared, {record}, {}, &at_centre, 3).empty());
  EXPECT_FALSE(Match(prepared, {record}, {}, &at_centre, 30).empty());
  // Without an anchor offset the box centre is the anchor.
  record.centre_offset_px = cv::Point2f(0.0f, 0.0f);
  EXPECT_FALSE(Match(prepared, {record}, {}, &at_centre, 3).empty());
  const std::vector<cv::Point> none;
  EXPECT_TRUE(Match(prepared, {record}, {}, &none, 100).empty());
}

TEST(MatcherTest, EightBitTemplatesAndSingleLevelTemplatesAreFoundToo) {
  cv::RNG rng(62);
  test::TestScene scene = test::RandomScene({300, 200}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  const cv::Rect box(97, 61, 50, 40);
  TemplateRecord small = test::TemplateFromScene(scene, box, 20, 1, rng);
  TemplateRecord single = test::TemplateFromScene(scene, box + cv::Point(1, 1), 63, 2, rng);
  single.levels.resize(1);
  for (const TemplateRecord& record : {small, single}) {
    const auto matches = Match(prepared, {record});
    ASSERT_FALSE(matches.empty()) << record.id;
    EXPECT_EQ(cv::Point(matches[0].x, matches[0].y), record.bbox_px.tl()) << record.id;
    EXPECT_FLOAT_EQ(matches[0].similarity_percent, 100.0f);
  }
}

TEST(MatcherTest, RgbOnlySceneScoresColourFeaturesOnly) {
  cv::RNG rng(63);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const TemplateRecord record = test::TemplateFromScene(scene, {150, 90, 60, 50}, 63, 3, rng);
  for (auto& level : scene.quantized) level[ModalityIndex(Modality::kDepthNormal)] = cv::Mat();
  const auto matches = Match(Prepare(scene), {record});
  ASSERT_FALSE(matches.empty());
  EXPECT_EQ(cv::Point(matches[0].x, matches[0].y), cv::Point(150, 90));
  EXPECT_FLOAT_EQ(matches[0].similarity_percent, 100.0f);
}

TEST(MatcherTest, LinearMemoriesAreBuiltOnlyForTheLevelsSearchedOnTheGrid) {
  cv::RNG rng(70);
  test::TestScene scene = test::RandomScene({200, 150}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  EXPECT_FALSE(prepared.Level(0).linearized);
  EXPECT_FALSE(prepared.Level(1).linearized);
  const TemplateRecord record = test::TemplateFromScene(scene, {20, 30, 50, 40}, 63, 1, rng);
  EXPECT_EQ(Match(prepared, {record}).size(), 1u);
  EXPECT_FALSE(prepared.Level(0).linearized);
  EXPECT_TRUE(prepared.Level(1).linearized);
  EXPECT_TRUE(prepared.LinearizedLevel(0).linearized);
}

TEST(MatcherTest, CandidatePointsRestrictTheSearch) {
  cv::RNG rng(64);
  test::TestScene scene = test::RandomScene({640, 480}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  const cv::Rect box(400, 250, 70, 60);
  const std::vector<TemplateRecord> records = {test::TemplateFromScene(scene, box, 63, 5, rng)};

  const std::vector<cv::Point> near = {{30, 30}, Centre(box) + cv::Point(9, -7)};
  auto matches = Match(prepared, records, {}, &near, 12);
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(cv::Point(matches[0].x, matches[0].y), box.tl());

  const std::vector<cv::Point> far = {{30, 30}, Centre(box) + cv::Point(80, 0), {600, 60}};
  EXPECT_TRUE(Match(prepared, records, {}, &far, 12).empty());
  const std::vector<cv::Point> none;
  EXPECT_TRUE(Match(prepared, records, {}, &none, 50).empty());
  EXPECT_THROW(Match(prepared, records, {}, &near, -1), Error);
}

TEST(MatcherTest, ThresholdRejectsAPartlyWrongTemplate) {
  cv::RNG rng(65);
  test::TestScene scene = test::RandomScene({320, 240}, 0.05, rng);
  const PreparedScene prepared = Prepare(scene);
  const cv::Rect box(100, 80, 64, 64);
  TemplateRecord record = test::TemplateFromScene(scene, box, 63, 9, rng);
  // Turn half of the features at every level by 90 deg (4 bins): they no longer match.
  for (TemplateLevel& level : record.levels) {
    for (std::size_t i = 0; i < level.features.size(); i += 2) {
      level.features[i].label = static_cast<std::uint8_t>((level.features[i].label + 4) % 8);
    }
  }
  MatchOptions strict;
  strict.threshold_percent = 90.0f;
  EXPECT_TRUE(Match(prepared, {record}, strict).empty());
  MatchOptions lenient;
  lenient.threshold_percent = 45.0f;
  const auto matches = Match(prepared, {record}, lenient);
  ASSERT_FALSE(matches.empty());
  EXPECT_NEAR(matches[0].x, box.x, 5);
  EXPECT_NEAR(matches[0].y, box.y, 5);
  for (const RawMatch& match : matches) {
    EXPECT_GE(match.similarity_percent, 45.0f);
    EXPECT_LT(match.similarity_percent, 90.0f);
  }
}

TEST(MatcherTest, NonMaximumSuppressionKeepsTheBestPerObjectAndPlace) {
  cv::RNG rng(66);
  test::TestScene scene = test::RandomScene({400, 300}, kDensity, rng);
  const cv::Rect box(50, 60, 60, 50);
  test::CopyPatch(scene, box, {250, 180});  // a second instance far away
  const PreparedScene prepared = Prepare(scene);
  TemplateRecord first = test::TemplateFromScene(scene, box, 63, 4, rng);
  TemplateRecord twin = first;  // same view again: a duplicate at each place
  twin.id = 2;
  MatchOptions one_per_place;
  one_per_place.matches_per_location = 1;
  const auto same_object = Match(prepared, {first, twin}, one_per_place);
  ASSERT_EQ(same_object.size(), 2u);  // one per instance, the lower id wins the tie
  for (const RawMatch& match : same_object) EXPECT_EQ(match.template_id, 2u);
  EXPECT_EQ(cv::Point(same_object[0].x, same_object[0].y), box.tl());
  EXPECT_EQ(cv::Point(same_object[1].x, same_object[1].y), cv::Point(250, 180));
  // Two per place: both templates at both instances.
  MatchOptions two_per_place;
  two_per_place.matches_per_location = 2;
  EXPECT_EQ(Match(prepared, {first, twin}, two_per_place).size(), 4u);
  // One template can reach a place from several coarse hits (here: the same record twice); it is
  // kept there once, however many matches a place may keep.
  MatchOptions three_per_place;
  three_per_place.matches_per_location = 3;
  EXPECT_EQ(Match(prepared, {first, first}, three_per_place).size(), 2u);

  twin.obj_id = 1;  // another object: never suppressed by the first
  EXPECT_EQ(Match(prepared, {first, twin}, one_per_place).size(), 4u);

  MatchOptions wide = one_per_place;
  wide.nms_radius_px = 400;  // everything of one object is one detection
  EXPECT_EQ(Match(prepared, {first}, wide).size(), 1u);
  MatchOptions capped;
  capped.max_matches = 1;
  EXPECT_EQ(Match(prepared, {first, twin}, capped).size(), 1u);
  one_per_place.matches_per_location = 0;
  EXPECT_THROW(Match(prepared, {first}, one_per_place), Error);
}

TEST(MatcherTest, OutputIsSortedAndDeterministic) {
  cv::RNG rng(67);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  std::vector<TemplateRecord> records;
  for (std::uint32_t id = 0; id < 24; ++id) {
    const cv::Rect box(rng.uniform(0, 260), rng.uniform(0, 190), 50, 40);
    records.push_back(test::TemplateFromScene(scene, box, 30, id, rng));
    records.back().obj_id = static_cast<int>(id);
  }
  MatchOptions options;
  options.threshold_percent = 60.0f;
  const auto matches = Match(prepared, records, options);
  ASSERT_GE(matches.size(), records.size());
  EXPECT_TRUE(
      std::is_sorted(matches.begin(), matches.end(), [](const RawMatch& a, const RawMatch& b) {
        return std::tie(b.similarity_percent, a.template_id, a.y, a.x) <
               std::tie(a.similarity_percent, b.template_id, b.y, b.x);
      }));
  for (int run = 0; run < 3; ++run) EXPECT_EQ(Match(prepared, records, options), matches);
  {
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(Match(prepared, records, options), matches);
  }
  // Every SIMD path, in scene preparation and in matching, gives the same answer.
  for (SimdPath path : SupportedSimdPaths()) {
    MatchOptions forced = options;
    forced.simd = path;
    EXPECT_EQ(Match(PreparedScene(scene.quantized, scene.spread_px, path), records, forced),
              matches)
        << SimdPathName(path);
  }
}

TEST(MatcherTest, NothingToMatchGivesNoMatchesAndNoCrash) {
  cv::RNG rng(68);
  test::TestScene scene = test::RandomScene({120, 90}, kDensity, rng);
  const TemplateRecord record = test::TemplateFromScene(scene, {10, 10, 40, 30}, 63, 1, rng);
  EXPECT_TRUE(Match(PreparedScene(), {record}).empty());
  EXPECT_TRUE(Match(Prepare(scene), {}).empty());
  // A scene with no modality at all, and an all-zero scene.
  EXPECT_TRUE(Match(PreparedScene({{cv::Mat(), cv::Mat()}}, {5}), {record}).empty());
  const cv::Mat zeros = cv::Mat::zeros(90, 120, CV_8UC1);
  EXPECT_TRUE(Match(PreparedScene({{zeros, zeros}}, {5}), {record}).empty());

  TemplateRecord empty = record;
  for (TemplateLevel& level : empty.levels) level.features.clear();
  TemplateRecord no_levels = record;
  no_levels.levels.clear();
  TemplateRecord weak = record;
  weak.status = TemplateStatus::kTooFewFeatures;
  TemplateRecord huge = record;
  huge.levels[0].width = 500;
  EXPECT_TRUE(Match(Prepare(scene), {empty, no_levels, weak, huge}).empty());
}

// Facts worked out once per template give the matches that reading the features per frame
// gives, on a scene with both modalities and on one with colour only.
TEST(MatcherTest, TemplateFactsGiveTheSameMatches) {
  cv::RNG rng(71);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  std::vector<TemplateRecord> records;
  for (std::uint32_t id = 0; id < 6; ++id) {
    const cv::Rect box(20 + 40 * static_cast<int>(id), 30 + 25 * static_cast<int>(id), 60, 50);
    records.push_back(test::TemplateFromScene(scene, box, 63, id, rng));
  }
  std::vector<TemplateFacts> facts;
  std::vector<TemplateFacts> grid_facts;  // with the top level's grid features
  for (const TemplateRecord& record : records) {
    facts.push_back(TemplateFactsOf(record));
    grid_facts.push_back(TemplateFactsOf(record, scene.spread_px));
    ASSERT_FALSE(grid_facts.back().back().grid_features.empty());
    ASSERT_TRUE(grid_facts.back().front().grid_features.empty());  // level 0: not on the grid
  }
  for (const bool colour_only : {false, true}) {
    if (colour_only) {
      for (auto& level : scene.quantized) level[ModalityIndex(Modality::kDepthNormal)] = cv::Mat();
    }
    const PreparedScene prepared = Prepare(scene);
    const std::vector<RawMatch> without = Match(prepared, records);
    for (const std::vector<TemplateFacts>* given : {&facts, &grid_facts}) {
      TemplateSearch search{records, nullptr, {}};
      search.facts = *given;
      const std::vector<RawMatch> with =
          MatchTemplateGroups(prepared, std::span<const TemplateSearch>(&search, 1), {});
      ASSERT_EQ(with.size(), without.size()) << colour_only;
      ASSERT_FALSE(with.empty());
      for (std::size_t i = 0; i < with.size(); ++i) {
        EXPECT_EQ(with[i].template_id, without[i].template_id);
        EXPECT_EQ(cv::Point(with[i].x, with[i].y), cv::Point(without[i].x, without[i].y));
        EXPECT_EQ(with[i].similarity_percent, without[i].similarity_percent);
      }
    }
  }
  // Facts for another number of templates are refused.
  TemplateSearch short_search{records, nullptr, {}};
  short_search.facts = std::span<const TemplateFacts>(facts).first(2);
  EXPECT_THROW(
      MatchTemplateGroups(Prepare(scene), std::span<const TemplateSearch>(&short_search, 1), {}),
      Error);
}

TEST(MatcherTest, BadInputsThrowClearErrors) {
  cv::RNG rng(69);
  test::TestScene scene = test::RandomScene({120, 90}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  TemplateRecord record = test::TemplateFromScene(scene, {10, 10, 40, 30}, 63, 42, rng);
  record.levels[0].features[0].label = 9;
  try {
    Match(prepared, {record});
    FAIL() << "expected Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("template 42"), std::string::npos) << error.what();
  }
  try {
    TemplateFactsOf(record);  // the same check, once per template
    FAIL() << "expected Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("template 42"), std::string::npos) << error.what();
  }
  MatchOptions options;
  options.threshold_percent = 0.0f;
  EXPECT_THROW(options.Validate(), Error);
  options = {};
  options.nms_radius_px = -1;
  EXPECT_THROW(options.Validate(), Error);
  options = {};
  options.max_matches = 0;
  EXPECT_THROW(options.Validate(), Error);
  options = {};
  options.max_candidates_per_template = 0;
  EXPECT_THROW(options.Validate(), Error);
  EXPECT_NO_THROW(MatchOptions().Validate());
  EXPECT_THROW(PreparedScene(scene.quantized, {5}), Error);  // one T for two levels
  EXPECT_THROW(prepared.Level(2), Error);
}

TEST(MatcherTest, TheRefinementBudgetKeepsTheBestTopLevelHits) {
  cv::RNG rng(67);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  // Five templates cut from the scene at distinct places: each scores 100 % at its own place.
  std::vector<TemplateRecord> records;
  for (int i = 0; i < 5; ++i) {
    records.push_back(test::TemplateFromScene(scene, {20 + 55 * i, 40 + 30 * i, 40, 40}, 63,
                                              static_cast<std::uint32_t>(i), rng));
  }
  MatchOptions options;
  options.threshold_percent = 95.0f;
  std::vector<std::uint32_t> found;
  for (const RawMatch& match : Match(prepared, records, options))
    found.push_back(match.template_id);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  // With room for one refinement, only the best top-level hit is refined: all tie at 100 %,
  // so the lowest template id wins.
  options.max_refinements = 1;
  const std::vector<RawMatch> budgeted = Match(prepared, records, options);
  ASSERT_EQ(budgeted.size(), 1u);
  EXPECT_EQ(budgeted[0].template_id, 0u);
  EXPECT_EQ(cv::Point(budgeted[0].x, budgeted[0].y), cv::Point(20, 40));
  options.max_refinements = 0;
  EXPECT_THROW(Match(prepared, records, options), Error);
}

TEST(MatcherTest, TheRefinementBudgetGoesToHitsThatStandOutFromTheirTemplatesOtherCells) {
  cv::RNG rng(72);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  // The right three quarters of the scene: orientation 0 everywhere, at both levels.
  const cv::Rect uniform(80, 0, 240, 240);
  for (std::size_t level = 0; level < scene.quantized.size(); ++level) {
    const int shift = static_cast<int>(level);
    const cv::Rect scaled(uniform.x >> shift, uniform.y >> shift, uniform.width >> shift,
                          uniform.height >> shift);
    for (cv::Mat& modality : scene.quantized[level]) modality(scaled).setTo(1);
  }
  const PreparedScene prepared = Prepare(scene);
  // Template 0, cut from the uniform part, an eighth of its features one bin off: 91 % on all of
  // that part. Template 1, cut from the random part, a third of its features turned by 90 deg:
  // less at its own place only.
  TemplateRecord everywhere = test::TemplateFromScene(scene, {200, 100, 40, 40}, 63, 0, rng);
  TemplateRecord once = test::TemplateFromScene(scene, {20, 100, 40, 40}, 63, 1, rng);
  for (std::size_t l = 0; l < everywhere.levels.size(); ++l) {
    for (std::size_t i = 0; i < everywhere.levels[l].features.size(); i += 8) {
      everywhere.levels[l].features[i].label = 1;
    }
    for (std::size_t i = 0; i < once.levels[l].features.size(); i += 3) {
      Feature& feature = once.levels[l].features[i];
      feature.label = static_cast<std::uint8_t>((feature.label + 4) % 8);
    }
  }
  MatchOptions options;
  options.threshold_percent = 60.0f;
  const std::vector<RawMatch> all = Match(prepared, {everywhere, once}, options);
  const auto best_of = [&](std::uint32_t id) {
    float best = 0.0f;
    for (const RawMatch& match : all) {
      if (match.template_id == id) best = std::max(best, match.similarity_percent);
    }
    return best;
  };
  ASSERT_GT(best_of(0), best_of(1)) << "the uniform template must score higher";
  // One refinement: the hit that rises above its template's other cells, not the higher one.
  options.max_refinements = 1;
  const std::vector<RawMatch> budgeted = Match(prepared, {everywhere, once}, options);
  ASSERT_EQ(budgeted.size(), 1u);
  EXPECT_EQ(budgeted[0].template_id, 1u);
  // Its own place, give or take the turned features' pull.
  EXPECT_NEAR(budgeted[0].x, 20, 4);
  EXPECT_NEAR(budgeted[0].y, 100, 4);
}

TEST(MatcherTest, CandidatePointsOutsideTheImageReachOnlyNearbyTemplates) {
  cv::RNG rng(68);
  test::TestScene scene = test::RandomScene({200, 150}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  const cv::Rect box(0, 0, 40, 40);
  TemplateRecord record = test::TemplateFromScene(scene, box, 63, 9, rng);
  record.centre_offset_px = cv::Point2f(2.0f, 2.0f);
  // A point just outside the top-left corner is within 5 px of the anchor (2, 2).
  const std::vector<cv::Point> outside = {cv::Point(-1, -1)};
  const auto found = Match(prepared, {record}, {}, &outside, 5);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(cv::Point(found[0].x, found[0].y), box.tl());
  const std::vector<cv::Point> far_outside = {cv::Point(-500, -500)};
  EXPECT_TRUE(Match(prepared, {record}, {}, &far_outside, 5).empty());
}

TEST(MatcherTest, TemplateGroupsShareOneRefinementBudget) {
  cv::RNG rng(69);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  std::vector<TemplateRecord> left;
  std::vector<TemplateRecord> right;
  for (int i = 0; i < 3; ++i) {
    left.push_back(test::TemplateFromScene(scene, {10 + 30 * i, 20, 40, 40}, 63,
                                           static_cast<std::uint32_t>(i), rng));
    right.push_back(test::TemplateFromScene(scene, {200, 20 + 60 * i, 40, 40}, 63,
                                            static_cast<std::uint32_t>(10 + i), rng));
  }
  MatchOptions options;
  options.threshold_percent = 95.0f;
  options.max_refinements = 2;
  const std::vector<TemplateSearch> searches = {{left, nullptr, {}}, {right, nullptr, {}}};
  const std::vector<RawMatch> matches = MatchTemplateGroups(prepared, searches, options);
  // Two refinements over both groups: the best two top-level hits, which all tie at 100 %, so
  // the two lowest ids, both of the left group.
  ASSERT_EQ(matches.size(), 2u);
  std::vector<std::uint32_t> ids = {matches[0].template_id, matches[1].template_id};
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<std::uint32_t>{0, 1}));
  // The same as the templates in one set.
  std::vector<TemplateRecord> all = left;
  all.insert(all.end(), right.begin(), right.end());
  EXPECT_EQ(Match(prepared, all, options), matches);
  // Candidate points per group: the right set searched only around its second template.
  const std::vector<cv::Point> near_second = {cv::Point(220, 100)};
  const std::vector<TemplateSearch> restricted = {{right, &near_second, {}}};
  options.max_refinements = 10;
  const std::vector<RawMatch> found = MatchTemplateGroups(prepared, restricted, options, 4);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].template_id, 11u);
}

TEST(MatcherTest, TreeSearchScoresOnlyTheMembersOfTheBestClusters) {
  cv::RNG rng(71);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  test::TestScene elsewhere = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  // Cluster 0: a representative and a member that both match. Cluster 1: a representative
  // from another scene (no match) and a member that matches.
  std::vector<TemplateRecord> templates = {
      test::TemplateFromScene(scene, {20, 20, 40, 40}, 63, 0, rng),
      test::TemplateFromScene(scene, {120, 20, 40, 40}, 63, 1, rng),
      test::TemplateFromScene(elsewhere, {20, 120, 40, 40}, 63, 2, rng),
      test::TemplateFromScene(scene, {220, 120, 40, 40}, 63, 3, rng)};
  const std::vector<ViewCluster> clusters = {{0, {0, 1}}, {2, {2, 3}}};
  MatchOptions options;
  options.threshold_percent = 95.0f;
  const auto ids = [&](float descend) {
    options.tree_descend = descend;
    const std::vector<TemplateSearch> search = {{templates, nullptr, clusters}};
    std::set<std::uint32_t> found;
    for (const RawMatch& match : MatchTemplateGroups(prepared, search, options)) {
      found.insert(match.template_id);
    }
    return found;
  };
  EXPECT_EQ(ids(0.5f), (std::set<std::uint32_t>{0, 1}));     // only the best cluster
  EXPECT_EQ(ids(1.0f), (std::set<std::uint32_t>{0, 1, 3}));  // every template: the flat search
  options.search = TemplateSearchMode::kFlat;
  EXPECT_EQ(ids(0.5f), (std::set<std::uint32_t>{0, 1, 3}));  // the flat search ignores the share
  options.search = TemplateSearchMode::kTree;
  options.tree_descend = 1.0f;
  EXPECT_EQ(
      MatchTemplateGroups(prepared, std::vector<TemplateSearch>{{templates, nullptr, {}}}, options),
      MatchTemplateGroups(prepared, std::vector<TemplateSearch>{{templates, nullptr, clusters}},
                          options));
  options.tree_descend = 0.0f;
  EXPECT_THROW(options.Validate(), Error);
}

TEST(MatcherTest, ATreeSearchRefinesWithinTheTreeBudget) {
  cv::RNG rng(73);
  test::TestScene scene = test::RandomScene({320, 240}, kDensity, rng);
  const PreparedScene prepared = Prepare(scene);
  // Two clusters of two templates each, all four found where they were cut from.
  std::vector<TemplateRecord> templates;
  for (int i = 0; i < 4; ++i) {
    templates.push_back(test::TemplateFromScene(scene, {20 + 70 * i, 60, 40, 40}, 63,
                                                static_cast<std::uint32_t>(i), rng));
  }
  const std::vector<ViewCluster> clusters = {{0, {0, 1}}, {2, {2, 3}}};
  const std::vector<TemplateSearch> search = {{templates, nullptr, clusters}};
  MatchOptions options;
  options.threshold_percent = 95.0f;
  options.tree_descend = 0.99f;  // both clusters descended, through the tree
  options.max_refinements = 4;
  options.tree_refinements = 1;
  EXPECT_EQ(MatchTemplateGroups(prepared, search, options).size(), 1u);
  options.tree_refinements = 3;
  EXPECT_EQ(MatchTemplateGroups(prepared, search, options).size(), 3u);
  // The flat search over the same templates keeps max_refinements.
  options.search = TemplateSearchMode::kFlat;
  EXPECT_EQ(MatchTemplateGroups(prepared, search, options).size(), 4u);
  options.tree_refinements = 0;
  EXPECT_THROW(options.Validate(), Error);
}

}  // namespace
}  // namespace layermod
