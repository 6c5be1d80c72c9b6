// SPDX-License-Identifier: MIT
// The bench's bookkeeping on a tiny synthetic dataset (no timing is asserted: speed belongs in
// `layermod bench` runs, not in tests).
#include "eval/bench.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "eval_fixtures.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr int kImages = 3;

TEST(BenchTest, RunsTheThreeMethodsOnTheSameFrames) {
  test::TempDir dir;
  const test::TinyEvalData data = test::MakeTinyEvalData(dir.path(), kImages);
  const Detector detector({data.archive});
  const BenchResult result = RunBench(detector, BenchSuite::kDepth, {}, data.dataset, {}, {});
  EXPECT_EQ(result.templates, data.archive.templates().size());
  ASSERT_EQ(result.methods.size(), 3u);
  EXPECT_EQ(result.methods[0].name, "scene-patch");
  EXPECT_EQ(result.methods[1].name, "exhaustive");
  EXPECT_EQ(result.methods[2].name, "cv::linemod");
  for (const MethodSummary& method : result.methods) {
    EXPECT_EQ(method.frames, kImages);
    EXPECT_EQ(method.overall.frames, kImages);
    EXPECT_LE(method.overall.correct, method.overall.detected);
    EXPECT_LE(method.median_frame_ms, method.p90_frame_ms);
  }

  EvalRunInfo info;
  info.dataset_dir = data.dataset.string();
  const nlohmann::json json = BenchReportJson(info, result);
  ASSERT_EQ(json["methods"].size(), 3u);
  EXPECT_EQ(json["methods"][2]["method"], "cv::linemod");
  EXPECT_EQ(json["methods"][1]["frames"], kImages);
  ASSERT_EQ(json["ratios"].size(), 2u);
  EXPECT_EQ(json["ratios"][0]["relative_to"], "scene-patch");
  const double expected_ratio =
      result.methods[0].median_frame_ms > 0.0
          ? result.methods[1].median_frame_ms / result.methods[0].median_frame_ms
          : 0.0;
  EXPECT_DOUBLE_EQ(json["ratios"][0]["median_time_ratio"].get<double>(), expected_ratio);
  EXPECT_EQ(json["linemod_training"]["templates"], result.linemod_training.templates);
  EXPECT_THAT(BenchTable(result), ::testing::HasSubstr("| cv::linemod | 3 |"));
}

TEST(BenchTest, ColourOnlySuiteRunsWithoutDepth) {
  test::TempDir dir;
  const test::TinyEvalData data = test::MakeTinyEvalData(dir.path(), kImages);
  std::filesystem::remove_all(data.dataset / "test" / "000001" / "depth");
  const Detector detector({data.archive});
  EXPECT_THROW(RunBench(detector, BenchSuite::kDepth, {}, data.dataset, {}, {}), Error);
  const BenchResult result = RunBench(detector, BenchSuite::kColorOnly, {}, data.dataset, {}, {});
  ASSERT_EQ(result.methods.size(), 2u);
  EXPECT_EQ(result.methods[0].name, "color-only");
  EXPECT_EQ(result.methods[1].name, "cv::linemod LINE-2D");
  EXPECT_EQ(result.methods[1].frames, kImages);
}

TEST(BenchTest, TreeVsFlatSuiteRunsBothSearchesWithoutLinemod) {
  test::TempDir dir;
  const test::TinyEvalData data = test::MakeTinyEvalData(dir.path(), kImages);
  const Detector detector({data.archive});
  const BenchResult result = RunBench(detector, BenchSuite::kTreeVsFlat, {}, data.dataset, {}, {});
  ASSERT_EQ(result.methods.size(), 2u);
  EXPECT_EQ(result.methods[0].name, "scene-patch tree");
  EXPECT_EQ(result.methods[1].name, "scene-patch flat");
  EXPECT_EQ(result.linemod_training.templates, 0);  // cv::linemod is not built
  // A few dozen templates per layer get no view tree: both runs are the same flat search.
  EXPECT_EQ(result.methods[0].overall.correct, result.methods[1].overall.correct);
  EXPECT_EQ(result.methods[0].overall.detected, result.methods[1].overall.detected);
  EXPECT_EQ(result.methods[1].frames, kImages);
  EXPECT_EQ(SuiteName(result.suite), "tree-vs-flat");
}

TEST(BenchTest, TreeVsFlatSuiteRunsInTheModeAskedFor) {
  test::TempDir dir;
  const test::TinyEvalData data = test::MakeTinyEvalData(dir.path(), kImages);
  const Detector detector({data.archive});
  DetectorOptions options;
  options.mode = DetectionMode::kExhaustive;
  const BenchResult result =
      RunBench(detector, BenchSuite::kTreeVsFlat, options, data.dataset, {}, {});
  ASSERT_EQ(result.methods.size(), 2u);
  EXPECT_EQ(result.methods[0].name, "exhaustive tree");
  EXPECT_EQ(result.methods[1].name, "exhaustive flat");
  // The same as the depth suite's exhaustive run, which the options' mode does not change.
  const BenchResult depth = RunBench(detector, BenchSuite::kDepth, {}, data.dataset, {}, {});
  ASSERT_EQ(depth.methods[1].name, "exhaustive");
  EXPECT_EQ(result.methods[0].overall.correct, depth.methods[1].overall.correct);
  EXPECT_EQ(result.methods[0].overall.detected, depth.methods[1].overall.detected);
}

}  // namespace
}  // namespace layermod
