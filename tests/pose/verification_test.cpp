// SPDX-License-Identifier: MIT
#include "pose/verification.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "features/quantize.h"
#include "pose/pose_test_scene.h"
#include "render/rasterizer.h"

namespace layermod {
namespace {

TEST(VerificationTest, AcceptsTheTruePose) {
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const Verification result =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_TRUE(result.accepted);
  EXPECT_GT(result.depth_inlier_ratio, 0.98);
  EXPECT_GT(result.visible_ratio, 0.98);
  EXPECT_GT(result.depth_fit, 0.95);
}

TEST(VerificationTest, DepthFitFallsWithTheDistanceToTheTruePose) {
  // The whole part 5 mm too far: every pixel is still an inlier (tolerance 15 mm), but each
  // agrees only to 1 - 5/15. Background pixels the shifted silhouette now covers are
  // contradicted and count 0, so the fit lies a little below.
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const Pose farther = test::Perturb(truth, 0.0, {0, 0, 1}, truth.t.normalized() * 5.0);
  const Verification result =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), farther, scene.depth_mm, scene.color);
  EXPECT_TRUE(result.accepted);
  EXPECT_GT(result.depth_inlier_ratio, 0.9);
  EXPECT_NEAR(result.depth_fit, 1.0 - 5.0 / 15.0, 0.08);
  EXPECT_LT(result.depth_fit, result.depth_inlier_ratio - 0.2);
}

TEST(VerificationTest, RejectsAPoseWhereTheObjectIsNot) {
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const Pose elsewhere = test::Perturb(truth, 0.0, {0, 0, 1}, {150.0, 0.0, 0.0});
  const Verification result = VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), elsewhere,
                                         scene.depth_mm, scene.color);
  EXPECT_FALSE(result.accepted);
  EXPECT_LT(result.depth_inlier_ratio, 0.3);
}

TEST(VerificationTest, OccludersAreNotCountedAgainstThePose) {
  const Pose truth = test::SamplePose(800.0);
  test::TestScene scene = test::RenderTestScene(truth);
  // A bar in front of the left half of the image.
  scene.depth_mm(cv::Rect(0, 0, 330, 480)).setTo(500.0f);
  const Verification result =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_GT(result.depth_inlier_ratio, 0.98);  // occluded pixels are neither for nor against
  EXPECT_GT(result.visible_ratio, 0.98);
}

TEST(VerificationTest, TellsOcclusionFromContradiction) {
  const Pose truth = test::SamplePose(800.0);
  test::TestScene occluded = test::RenderTestScene(truth);
  occluded.depth_mm.setTo(500.0f);  // everything in front of the part: all occluded
  const Verification in_front = VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth,
                                           occluded.depth_mm, occluded.color);
  EXPECT_GT(in_front.occluded_ratio, 0.99);
  EXPECT_LT(in_front.contradicted_ratio, 0.01);

  test::TestScene empty = test::RenderTestScene(truth);
  empty.depth_mm.setTo(1200.0f);  // only the wall behind: the part is not there
  const Verification behind =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, empty.depth_mm, empty.color);
  EXPECT_GT(behind.contradicted_ratio, 0.99);
  EXPECT_LT(behind.occluded_ratio, 0.01);
  EXPECT_FALSE(behind.accepted);
}

TEST(VerificationTest, SurfaceContinuingPastTheOutlineIsMeasured) {
  // The true pose in front of a far wall: the ring outside the outline sees the wall, not the
  // part's surface. The same pose "found" on a flat surface at the part's depth: the surface
  // goes on past the outline all round.
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const Verification isolated =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_LT(isolated.surface_continuation, 0.1);

  // The part's own depth carried outwards, ten pixels beyond its outline: a surface that goes
  // on where the part ends.
  cv::Mat flat = scene.depth_mm.clone();
  flat.setTo(0.0f, scene.depth_mm >= 1199.0f);
  for (int step = 0; step < 10; ++step) {
    cv::Mat grown;
    cv::dilate(flat, grown, cv::Mat());
    grown.copyTo(flat, flat == 0.0f);
  }
  const Verification on_surface =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, flat, scene.color);
  EXPECT_GT(on_surface.surface_continuation, 0.5);
}

GradientLabels WholeImageGradients(const cv::Mat& color) {
  return {QuantizeColorGradients(color, 10.0f), cv::Point(0, 0)};
}

TEST(VerificationTest, OutlineAgreementFallsWhenThePoseTurnsInTheImage) {
  // The part's outline lies on the scene's gradients at the true pose; turned 20 degrees about
  // the optical axis most of it lies beside them. Without gradients it is not judged.
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const GradientLabels gradients = WholeImageGradients(scene.color);
  const Verification right = VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth,
                                        scene.depth_mm, scene.color, {}, gradients);
  EXPECT_GT(right.outline_agreement, 0.9);
  const Pose turned = test::Perturb(truth, 20.0, truth.t.normalized(), {0.0, 0.0, 0.0});
  const Verification wrong = VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), turned,
                                        scene.depth_mm, scene.color, {}, gradients);
  EXPECT_LT(wrong.outline_agreement, right.outline_agreement - 0.3);
  const Verification unjudged =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_EQ(unjudged.outline_agreement, 0.0);
}

TEST(VerificationTest, OutlineAgreementIgnoresTheOutlineBehindAnOccluder) {
  // A bar in front of the left part of the image, with its own strong edge: the outline behind
  // it is not judged, so the agreement stays that of the visible outline.
  const Pose truth = test::SamplePose(800.0);
  test::TestScene scene = test::RenderTestScene(truth);
  scene.depth_mm(cv::Rect(0, 0, 320, 480)).setTo(500.0f);
  scene.color(cv::Rect(0, 0, 320, 480)).setTo(cv::Scalar(90, 90, 90));
  const Verification result =
      VerifyPose(test::SampleRenderMesh(), test::VgaCamera(), truth, scene.depth_mm, scene.color,
                 {}, WholeImageGradients(scene.color));
  EXPECT_GT(result.outline_agreement, 0.9);
}

TEST(VerificationTest, ColourDisagreementRejectsASaturatedModel) {
  // A saturated red model against a scene whose pixels are blue at the same depth.
  RenderMesh red = test::SampleRenderMesh();
  for (auto& color : red.colors) color = Eigen::Vector3f(0.9f, 0.1f, 0.1f);
  const Pose truth = test::SamplePose(800.0);
  test::TestScene scene = test::RenderTestScene(truth);
  scene.color.setTo(cv::Scalar(200, 40, 40));  // BGR blue
  const Verification result =
      VerifyPose(red, test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_LT(result.color_agreement, 0.1);
  EXPECT_FALSE(result.accepted);
}

TEST(VerificationTest, AnOccludersColourIsNotCountedAgainstThePose) {
  // A saturated red model; a blue bar in front of the left part of the image hides part of it.
  RenderMesh red = test::SampleRenderMesh();
  for (auto& color : red.colors) color = Eigen::Vector3f(0.9f, 0.1f, 0.1f);
  const Pose truth = test::SamplePose(800.0);
  test::TestScene scene = test::RenderTestScene(truth);
  const RenderedView seen = RenderView(red, test::VgaCamera(), truth);
  seen.color.copyTo(scene.color(seen.roi), seen.mask);
  const cv::Rect bar(0, 0, seen.roi.x + seen.roi.width / 2, 480);
  scene.color(bar).setTo(cv::Scalar(200, 40, 40));  // BGR blue
  const Verification without_depth =
      VerifyPose(red, test::VgaCamera(), truth, cv::Mat(), scene.color);
  EXPECT_LT(without_depth.color_agreement, 0.7);  // the bar's pixels count as disagreeing
  scene.depth_mm(bar).setTo(500.0f);
  const Verification with_depth =
      VerifyPose(red, test::VgaCamera(), truth, scene.depth_mm, scene.color);
  EXPECT_GT(with_depth.color_agreement, 0.95);  // they are seen to be in front: not judged
}

}  // namespace
}  // namespace layermod
