// SPDX-License-Identifier: MIT
// Occlusion-aware matching (DetectorOptions::occlusion) end to end on the bundled bracket's
// frame; the matching itself is tested in tests/match/occluders_test.cpp.
#include <gtest/gtest.h>

#include "bracket_frame.h"
#include "pipeline/detector.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(OccludedDetectionTest, WithNothingInFrontAwareMatchingGivesTheSameDetections) {
  DetectorOptions options;
  options.min_confidence = 0.0;
  ASSERT_EQ(options.occlusion, OcclusionMode::kAware);  // the default (BracketFrame().result)
  options.occlusion = OcclusionMode::kIgnore;
  const DetectionResult ignore =
      test::BracketFrame().detector.Detect(test::BracketFrame().capture, options);
  const DetectionResult& aware = test::BracketFrame().result;
  ASSERT_FALSE(aware.detections.empty());
  ASSERT_EQ(aware.detections.size(), ignore.detections.size());
  for (std::size_t i = 0; i < aware.detections.size(); ++i) {
    EXPECT_EQ(aware.detections[i].template_id, ignore.detections[i].template_id);
    EXPECT_FLOAT_EQ(aware.detections[i].score, ignore.detections[i].score);
    EXPECT_EQ(aware.detections[i].cam_from_model.t, ignore.detections[i].cam_from_model.t);
  }
}

TEST(OccludedDetectionTest, OcclusionModesHaveNamesAndUnknownOnesAreRefused) {
  for (const OcclusionMode mode : {OcclusionMode::kAware, OcclusionMode::kIgnore}) {
    EXPECT_EQ(ParseOcclusionMode(OcclusionModeName(mode)), mode);
  }
  EXPECT_THROW(ParseOcclusionMode("sometimes"), Error);
}

}  // namespace
}  // namespace layermod
