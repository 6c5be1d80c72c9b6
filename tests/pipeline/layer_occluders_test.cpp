// SPDX-License-Identifier: MIT
#include "pipeline/layer_occluders.h"
#include "support/test_cameras.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace layermod {
namespace {

TEST(SharedBoundTest, RoundsTheLayersBoundDownToItsStep) {
  for (const double depth_mm : {480.0, 650.0, 777.0, 1000.0, 1234.5, 1500.0}) {
    for (const double radius_mm : {40.0, 85.0, 130.0}) {
      const double bound_mm = NearestSurfaceMm(depth_mm, radius_mm);
      const int shared_mm = SharedBoundMm(depth_mm, radius_mm);
      EXPECT_EQ(shared_mm % kOccluderBoundStepMm, 0) << depth_mm << " " << radius_mm;
      EXPECT_LE(shared_mm, bound_mm);  // never nearer to the object than its own bound
      EXPECT_GT(shared_mm, bound_mm - kOccluderBoundStepMm);
    }
  }
}

// A textured frame at 1000 mm with a box at 600 mm in front of it, prepared over the whole image
// and, with `padding_px` > 0, that far past it (PrepareSceneRegion).
PreparedRegion FrameWithABoxInFront(int padding_px) {
  cv::RNG rng(5);
  cv::Mat color(480, 640, CV_8UC3);
  rng.fill(color, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(color, color, cv::Size(0, 0), 3.0);
  cv::Mat depth_mm(480, 640, CV_32F, cv::Scalar(1000.0f));
  depth_mm(cv::Rect(200, 160, 120, 80)).setTo(600.0f);
  return PrepareSceneRegion(color, depth_mm, test::RoundedKinectCamera(), FeatureOptions(),
                            cv::Rect(-padding_px, -padding_px, 640 + 2 * padding_px,
                                     480 + 2 * padding_px),
                            SimdPath::kAuto, padding_px);
}

TEST(OccluderBankTest, MarksWhatLiesNearerThanEachBoundAndNothingElse) {
  const PreparedRegion region = FrameWithABoxInFront(0);
  ASSERT_TRUE(region.outside_image.empty());
  const OccluderBank bank(region, {500, 800, 1050});
  EXPECT_EQ(bank.Find(500), nullptr);  // nothing is nearer than 500 mm
  EXPECT_EQ(bank.Find(650), nullptr);  // not built
  const Occluders* box_only = bank.Find(800);
  const Occluders* everything = bank.Find(1050);
  ASSERT_NE(box_only, nullptr);
  ASSERT_NE(everything, nullptr);
  ASSERT_EQ(box_only->masks.size(), static_cast<std::size_t>(region.scene.LevelCount()));
  const cv::Rect box = cv::Rect(200, 160, 120, 80) - region.region_px.tl();
  const cv::Mat& mask = box_only->masks.front();
  EXPECT_EQ(cv::countNonZero(mask), box.area());
  EXPECT_EQ(cv::countNonZero(mask(box)), box.area());
  EXPECT_EQ(box_only->hidden_credit, kHiddenFeatureScore);
  EXPECT_EQ(cv::countNonZero(everything->masks.front()), mask.size().area());
}

TEST(OccluderBankTest, HidesThePaddingPastTheImageAlongWithTheOccluders) {
  const PreparedRegion region = FrameWithABoxInFront(40);
  ASSERT_FALSE(region.outside_image.empty());
  const OccluderBank bank(region, {800});
  const Occluders* occluders = bank.Find(800);
  ASSERT_NE(occluders, nullptr);
  const cv::Mat& mask = occluders->masks.front();
  const cv::Mat& outside = region.outside_image.front();
  EXPECT_EQ(cv::countNonZero(mask), cv::countNonZero(outside) + 120 * 80);
  cv::Mat outside_kept;
  cv::bitwise_and(mask, outside, outside_kept);
  EXPECT_EQ(cv::countNonZero(outside_kept), cv::countNonZero(outside));
}

TEST(OccluderBankTest, ALayerCountsOutWhatLiesNearerThanItsOwnBoundWithinItsReach) {
  PreparedRegion region = FrameWithABoxInFront(0);
  const cv::Rect near_box = cv::Rect(200, 160, 120, 80) - region.region_px.tl();
  const cv::Rect second_box = cv::Rect(400, 300, 60, 50) - region.region_px.tl();
  region.depth_levels_mm.front()(second_box).setTo(803.0f);  // nearer than 807, not than 800
  // A layer at 900 mm of a part of radius 50 mm: bound 0.98 x 900 - 75 = 807 mm, shared 800.
  ASSERT_EQ(SharedBoundMm(900.0, 50.0), 800);
  const OccluderBank bank(region, {800});
  const Occluders* shared = bank.Find(800);
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(cv::countNonZero(shared->masks.front()), near_box.area());

  const std::optional<Occluders> layer =
      bank.ForLayer(900.0, 50.0, cv::Rect(cv::Point(0, 0), region.depth_levels_mm[0].size()));
  ASSERT_TRUE(layer.has_value());
  EXPECT_EQ(layer->ranked, shared->ranked);  // ranked on the shared copy, none made
  const cv::Mat& mask = layer->masks.front();
  EXPECT_EQ(cv::countNonZero(mask), near_box.area() + second_box.area());
  EXPECT_EQ(cv::countNonZero(mask(second_box)), second_box.area());

  const cv::Rect reach(near_box.tl() - cv::Point(10, 10), near_box.br() + cv::Point(10, 10));
  const std::optional<Occluders> near_only = bank.ForLayer(900.0, 50.0, reach);
  ASSERT_TRUE(near_only.has_value());
  EXPECT_EQ(cv::countNonZero(near_only->masks.front()), near_box.area());

  EXPECT_FALSE(bank.ForLayer(600.0, 50.0, reach).has_value());  // shared bound 500: not built
}

TEST(OccluderBankTest, WithoutDepthNothingIsAnOccluder) {
  cv::Mat color(120, 160, CV_8UC3, cv::Scalar(90, 120, 150));
  const PreparedRegion region =
      PrepareSceneRegion(color, cv::Mat(), test::RoundedKinectCamera(), FeatureOptions(),
                         cv::Rect(0, 0, 160, 120));
  const OccluderBank bank(region, {800});
  EXPECT_EQ(bank.Find(800), nullptr);
}

}  // namespace
}  // namespace layermod
