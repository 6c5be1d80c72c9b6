// SPDX-License-Identifier: MIT
#include "pipeline/detection_json.h"

#include <gtest/gtest.h>

#include "pipeline/detection_poses.h"

namespace layermod {
namespace {

Detection MakeDetection(float score, double depth_fit, double color_agreement) {
  Detection detection;
  detection.score = score;
  detection.verification.depth_fit = depth_fit;
  detection.verification.color_agreement = color_agreement;
  return detection;
}

TEST(DetectionJsonTest, PoseInBopConvention) {
  Detection detection;
  detection.obj_id = 8;
  detection.name = "driller";
  detection.cam_from_model.R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  detection.cam_from_model.t = Eigen::Vector3d(10, -20, 800);
  detection.ranking = 55.0;
  detection.verification.outline_agreement = 0.875;
  const nlohmann::ordered_json json = DetectionToJson(detection);
  EXPECT_EQ(json.at("obj_id"), 8);
  EXPECT_EQ(json.at("name"), "driller");
  EXPECT_EQ(json.at("cam_R_m2c"), nlohmann::ordered_json({0, -1, 0, 1, 0, 0, 0, 0, 1}));
  EXPECT_EQ(json.at("cam_t_m2c"), nlohmann::ordered_json({10, -20, 800}));
  EXPECT_DOUBLE_EQ(json.at("ranking").get<double>(), 55.0);
  EXPECT_DOUBLE_EQ(json.at("verification").at("outline_agreement").get<double>(), 0.875);
}

TEST(DetectionJsonTest, ResultListsDetectionsAndTimings) {
  DetectionResult result;
  result.detections.resize(2);
  result.timings.total_ms = 12.5;
  const nlohmann::ordered_json json = DetectionResultToJson(result, DetectionMode::kScenePatch);
  EXPECT_EQ(json.at("mode"), "scene-patch");
  EXPECT_EQ(json.at("detections").size(), 2u);
  EXPECT_DOUBLE_EQ(json.at("timings_ms").at("total").get<double>(), 12.5);
}

TEST(RankingTest, DepthFitOutweighsAFewPointsOfScore) {
  const Detection loose = MakeDetection(90.0f, 0.80, 1.0);
  const Detection tight = MakeDetection(86.0f, 0.95, 1.0);
  EXPECT_GT(RankingScore(tight, true), RankingScore(loose, true));
  // Without depth only score and colour count.
  EXPECT_GT(RankingScore(loose, false), RankingScore(tight, false));
  EXPECT_DOUBLE_EQ(RankingScore(MakeDetection(80.0f, 0.5, 0.5), true), 80.0 * 0.25 * 0.5);
}

TEST(RankingTest, OrdersByTheStoredRankingWithinEachSideOfTheLikelyConfidence) {
  Detection a = MakeDetection(95.0f, 1.0, 1.0);
  Detection b = MakeDetection(70.0f, 1.0, 1.0);
  a.ranking = 10.0;
  b.ranking = 20.0;
  for (const double confidence : {0.0, kLikelyConfidence - 0.01, kLikelyConfidence, 0.97}) {
    a.confidence = confidence;
    b.confidence = confidence;
    EXPECT_TRUE(RanksHigher(b, a)) << confidence;
    EXPECT_FALSE(RanksHigher(a, b)) << confidence;
  }
  // A likely right detection goes before an unlikely one, whatever their rankings.
  a.confidence = kLikelyConfidence;
  b.confidence = kLikelyConfidence - 0.01;
  EXPECT_TRUE(RanksHigher(a, b));
  EXPECT_FALSE(RanksHigher(b, a));
}

}  // namespace
}  // namespace layermod
