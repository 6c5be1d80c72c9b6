// SPDX-License-Identifier: MIT
#include "eval/eval_runner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_cameras.h"
#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {

using ::testing::HasSubstr;

// A 100 mm cube's corners: object 3 (plain) and object 4 (symmetric).
std::map<std::int32_t, EvalModel> CubeModels() {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(i & 1 ? 50 : -50, i & 2 ? 50 : -50, i & 4 ? 50 : -50);
  std::map<std::int32_t, EvalModel> models;
  models.emplace(3, EvalModel(3, 173.2, false, corners));
  models.emplace(4, EvalModel(4, 173.2, true, corners));
  return models;
}

Pose At(double x_mm, double z_mm) {
  Pose pose;
  pose.t = {x_mm, 0.0, z_mm};
  return pose;
}

// Two instances of object 3 (at x = -200 and x = +200) and one of object 4; object 7 is absent.
struct Frame {
  EvalFrame frame;
  BopFrame image;
};
Frame TwoInstanceFrame() {
  Frame f;
  f.frame.scene_id = 2;
  f.frame.image_id = 5;
  f.frame.targets = {{3, {0, 1}}, {4, {2}}};
  f.frame.absent = {7};
  f.image.camera = test::RoundVgaCamera();
  f.image.gt = {{3, At(-200, 1000)}, {3, At(200, 1000)}, {4, At(0, 900)}};
  return f;
}

Detection Found(std::int32_t obj_id, const Pose& pose, float score) {
  Detection detection;
  detection.obj_id = obj_id;
  detection.cam_from_model = pose;
  detection.score = score;
  detection.confidence = score / 100.0;
  return detection;
}

TEST(EvalRunnerTest, JudgesTheFirstDetectionAgainstTheClosestInstance) {
  const Frame f = TwoInstanceFrame();
  // Object 3's best detection lies 5 mm from the second instance; a worse one sits on the first.
  const std::vector<Detection> detections = {Found(3, At(205, 1000), 90.0f),
                                             Found(3, At(-200, 1000), 80.0f)};
  const std::vector<TargetOutcome> outcomes =
      ScoreFrame(f.frame, f.image, detections, CubeModels(), {}, 12.5);
  ASSERT_EQ(outcomes.size(), 3u);
  const TargetOutcome& cube = outcomes[0];
  EXPECT_EQ(cube.scene_id, 2);
  EXPECT_EQ(cube.image_id, 5);
  EXPECT_EQ(cube.obj_id, 3);
  EXPECT_TRUE(cube.present);
  EXPECT_TRUE(cube.detected);
  EXPECT_FLOAT_EQ(cube.score, 90.0f);
  EXPECT_NEAR(cube.pose.error_mm, 5.0, 1e-9);
  EXPECT_TRUE(cube.pose.correct);
  EXPECT_DOUBLE_EQ(cube.frame_time_ms, 12.5);
}

TEST(EvalRunnerTest, AnUndetectedTargetIsAMiss) {
  const Frame f = TwoInstanceFrame();
  const std::vector<TargetOutcome> outcomes =
      ScoreFrame(f.frame, f.image, {Found(3, At(-200, 1000), 90.0f)}, CubeModels(), {}, 1.0);
  EXPECT_EQ(outcomes[1].obj_id, 4);
  EXPECT_TRUE(outcomes[1].present);
  EXPECT_FALSE(outcomes[1].detected);
  EXPECT_FALSE(outcomes[1].pose.correct);
}

TEST(EvalRunnerTest, AWrongPoseIsDetectedButNotCorrect) {
  const Frame f = TwoInstanceFrame();
  const std::vector<TargetOutcome> outcomes =
      ScoreFrame(f.frame, f.image, {Found(4, At(0, 1100), 70.0f)}, CubeModels(), {}, 1.0);
  EXPECT_TRUE(outcomes[1].detected);
  // ADD-S, 200 mm too far: each corner's nearest is the one 100 or 200 mm from it, 150 mm on
  // average.
  EXPECT_NEAR(outcomes[1].pose.error_mm, 150.0, 1e-9);
  EXPECT_TRUE(outcomes[1].pose.symmetric_metric);
  EXPECT_FALSE(outcomes[1].pose.correct);
}

TEST(EvalRunnerTest, AnAbsentObjectsDetectionIsNotedAsAFalseOne) {
  const Frame f = TwoInstanceFrame();
  const std::vector<TargetOutcome> outcomes =
      ScoreFrame(f.frame, f.image, {Found(7, At(0, 800), 75.0f)}, CubeModels(), {}, 1.0);
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_EQ(outcomes[2].obj_id, 7);
  EXPECT_FALSE(outcomes[2].present);
  EXPECT_TRUE(outcomes[2].detected);
  EXPECT_DOUBLE_EQ(outcomes[2].confidence, 0.75);
}

TEST(EvalRunnerTest, ATargetWithoutAModelIsAnError) {
  Frame f = TwoInstanceFrame();
  f.frame.targets.push_back({9, {0}});
  EXPECT_THAT(
      test::ThrownMessage<Error>([&] { ScoreFrame(f.frame, f.image, {}, CubeModels(), {}, 1.0); }),
      HasSubstr("no model for object 9"));
}

}  // namespace
}  // namespace layermod
