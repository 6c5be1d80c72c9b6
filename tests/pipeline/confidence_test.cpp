// SPDX-License-Identifier: MIT
#include "pipeline/confidence.h"

#include <gtest/gtest.h>

namespace layermod {
namespace {

// A pose the scene confirms: high score, exact depth fit, nothing contradicted, its outline on
// the scene's edges.
Detection Confirmed() {
  Detection detection;
  detection.score = 92.0f;
  detection.verification.depth_fit = 0.9;
  detection.verification.depth_inlier_ratio = 0.98;
  detection.verification.visible_ratio = 0.99;
  detection.verification.color_agreement = 1.0;
  detection.verification.outline_agreement = 0.95;
  detection.icp.inlier_ratio = 0.97;
  detection.icp.rmse_mm = 2.0;
  return detection;
}

TEST(ConfidenceTest, FeaturesAreNamedAndScaled) {
  const ConfidenceFeatures features = FeaturesOf(Confirmed());
  EXPECT_EQ(ConfidenceFeatures::Names()[0], "score");
  EXPECT_DOUBLE_EQ(features.values[0], 0.92);
  EXPECT_DOUBLE_EQ(features.values[9], 0.2);  // ICP RMSE in cm
  EXPECT_EQ(ConfidenceFeatures::Names()[10], "outline_agreement");
  EXPECT_DOUBLE_EQ(features.values[10], 0.95);
}

TEST(ConfidenceTest, AnOutlineBesideTheScenesEdgesIsDoubtful) {
  // The depth fits as well, but the outline lies where the scene has no edge of its
  // orientation: a pose turned or shifted on a surface that fits it (docs/RESULTS.md).
  Detection beside = Confirmed();
  beside.verification.outline_agreement = 0.45;
  EXPECT_LT(DetectionConfidence(FeaturesOf(beside), true), 0.5);
  EXPECT_GT(DetectionConfidence(FeaturesOf(Confirmed()), true), 0.9);
}

TEST(ConfidenceTest, AConfirmedPoseIsConfidentAndAContradictedOneIsNot) {
  const double confirmed = DetectionConfidence(FeaturesOf(Confirmed()), true);
  Detection contradicted = Confirmed();
  contradicted.verification.depth_fit = 0.45;
  contradicted.verification.depth_inlier_ratio = 0.65;
  contradicted.verification.contradicted_ratio = 0.35;
  contradicted.verification.surface_continuation = 0.7;
  const double doubtful = DetectionConfidence(FeaturesOf(contradicted), true);
  EXPECT_GT(confirmed, 0.9);
  EXPECT_LT(doubtful, 0.5);
  EXPECT_GE(doubtful, 0.0);
  EXPECT_LE(confirmed, 1.0);
}

TEST(ConfidenceTest, GrowsWithTheScore) {
  Detection detection = Confirmed();
  double previous = 0.0;
  for (float score : {60.0f, 70.0f, 80.0f, 90.0f, 100.0f}) {
    detection.score = score;
    const double confidence = DetectionConfidence(FeaturesOf(detection), true);
    EXPECT_GT(confidence, previous) << "score " << score;
    previous = confidence;
  }
}

TEST(ConfidenceTest, WithoutDepthOnlyScoreAndColourCount) {
  Detection a = Confirmed();
  Detection b = Confirmed();
  b.verification.depth_fit = 0.0;  // not measured without depth
  b.verification.depth_inlier_ratio = 0.0;
  EXPECT_DOUBLE_EQ(DetectionConfidence(FeaturesOf(a), false),
                   DetectionConfidence(FeaturesOf(b), false));
  b.verification.color_agreement = 0.2;
  EXPECT_LT(DetectionConfidence(FeaturesOf(b), false), DetectionConfidence(FeaturesOf(a), false));
}

}  // namespace
}  // namespace layermod
