// SPDX-License-Identifier: MIT
#include "eval/eval_frames.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "util/error.h"

namespace layermod {
namespace {

BopGtInfo Visibility(double fraction) {
  BopGtInfo info;
  info.visib_fract = fraction;
  return info;
}

// Scene 1: image 0 shows objects 1 (0.9) and 2 (0.3); image 1 shows object 1 twice (0.2, 0.7).
// Scene 2 (no gt_info): image 5 shows object 2.
std::vector<BopScene> Scenes() {
  BopScene first;
  first.scene_id = 1;
  first.image_ids = {0, 1};
  first.has_gt_info = true;
  first.annotations[0].gt = {{1, {}}, {2, {}}};
  first.annotations[0].gt_info = {Visibility(0.9), Visibility(0.3)};
  first.annotations[1].gt = {{1, {}}, {1, {}}};
  first.annotations[1].gt_info = {Visibility(0.2), Visibility(0.7)};
  BopScene second;
  second.scene_id = 2;
  second.image_ids = {5};
  second.annotations[5].gt = {{2, {}}};
  return {first, second};
}

TEST(EvalFramesTest, KeepsVisibleInstancesOfKnownObjects) {
  const auto frames = SelectEvalFrames(Scenes(), {1, 2}, {}, "data");
  ASSERT_EQ(frames.size(), 3u);
  ASSERT_EQ(frames[0].targets.size(), 1u);  // object 2 at 0.3 is dropped
  EXPECT_EQ(frames[0].targets[0].obj_id, 1);
  EXPECT_EQ(frames[1].image_id, 1);
  EXPECT_EQ(frames[1].targets[0].gt_indices, std::vector<int>{1});
  EXPECT_EQ(frames[2].scene_index, 1u);  // no gt_info: every instance counts
  EXPECT_EQ(frames[2].targets[0].obj_id, 2);
}

TEST(EvalFramesTest, OnlyObjectsOfTheArchives) {
  FrameSelectionOptions options;
  options.absent_objects = false;
  const auto frames = SelectEvalFrames(Scenes(), {2}, options, "data");
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].scene_id, 2);
}

TEST(EvalFramesTest, ObjectsAFrameDoesNotShowAreJudgedAsAbsent) {
  // Object 2 in scene 1 image 0 is annotated but hardly visible: neither a target nor absent.
  // Image 1 does not show it at all; scene 2 image 5 shows it.
  const auto frames = SelectEvalFrames(Scenes(), {2}, {}, "data");
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].image_id, 1);
  EXPECT_TRUE(frames[0].targets.empty());
  EXPECT_EQ(frames[0].absent, std::vector<std::int32_t>{2});
  EXPECT_EQ(frames[1].scene_id, 2);
  EXPECT_TRUE(frames[1].absent.empty());
  ASSERT_EQ(frames[1].targets.size(), 1u);
}

TEST(EvalFramesTest, SceneTargetsAndFrameLimit) {
  FrameSelectionOptions options;
  options.scene_id = 1;
  EXPECT_EQ(SelectEvalFrames(Scenes(), {1, 2}, options, "data").size(), 2u);
  options.max_frames = 1;
  EXPECT_EQ(SelectEvalFrames(Scenes(), {1, 2}, options, "data").size(), 1u);
  options = {};
  options.absent_objects = false;
  options.targets = {{1, 1, 1, 1}, {2, 5, 3, 1}};  // object 3 is in no archive
  const auto frames = SelectEvalFrames(Scenes(), {1, 2}, options, "data");
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].image_id, 1);
  options.min_visib_fract = 0.0;
  EXPECT_EQ(SelectEvalFrames(Scenes(), {1, 2}, options, "data")[0].targets[0].gt_indices.size(),
            2u);
}

TEST(EvalFramesTest, ErrorsForUnknownTargetsAndEmptySelections) {
  FrameSelectionOptions options;
  options.targets = {{3, 0, 1, 1}};
  EXPECT_THROW(SelectEvalFrames(Scenes(), {1}, options, "data"), FormatError);
  try {
    SelectEvalFrames(Scenes(), {9}, {}, "data");
    FAIL() << "no exception";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("'data'"));
  }
  options = {};
  options.min_visib_fract = 1.5;
  EXPECT_THROW(SelectEvalFrames(Scenes(), {1}, options, "data"), Error);
}

}  // namespace
}  // namespace layermod
