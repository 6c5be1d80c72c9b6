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
  return PrepareSceneRegion(
      color, depth_mm, test::RoundedKinectCamera(), FeatureOptions(),
      cv::Rect(-padding_px, -padding_px, 640 + 2 * padding_px, 480 + 2 * padding_px),
      SimdPath::kAuto, padding_px);
}

// A layer of a part of radius 50 mm searched over `reach`: at 600 mm its bound is 513 mm (shared
// 500), at 900 mm 807 mm (shared 800), at 1200 mm 1101 mm (shared 1100).
LayerReach Layer(double depth_mm, const cv::Rect& reach) { return {depth_mm, 50.0, reach}; }

cv::Rect Everywhere(const PreparedRegion& region) {
  return cv::Rect(cv::Point(0, 0), region.depth_levels_mm.front().size());
}

TEST(OccluderBankTest, MarksWhatLiesNearerThanEachBoundAndNothingElse) {
  const PreparedRegion region = FrameWithABoxInFront(0);
  ASSERT_TRUE(region.outside_image.empty());
  const std::vector<LayerReach> layers = {Layer(600.0, Everywhere(region)),
                                          Layer(900.0, Everywhere(region)),
                                          Layer(1200.0, Everywhere(region))};
  const OccluderBank bank(region, layers);
  EXPECT_EQ(bank.Find(500), nullptr);  // nothing is nearer than 513 mm
  EXPECT_FALSE(bank.ForLayer(layers[0]).has_value());
  const Occluders* box_only = bank.Find(800);
  const Occluders* everything = bank.Find(1100);
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
  const LayerReach layer = Layer(900.0, Everywhere(region));
  const OccluderBank bank(region, std::vector<LayerReach>{layer});
  const cv::Mat& outside = region.outside_image.front();
  const std::optional<Occluders> own = bank.ForLayer(layer);
  ASSERT_TRUE(own.has_value());
  ASSERT_NE(bank.Find(800), nullptr);
  for (const cv::Mat& mask : {bank.Find(800)->masks.front(), own->masks.front()}) {
    EXPECT_EQ(cv::countNonZero(mask), cv::countNonZero(outside) + 120 * 80);
    cv::Mat outside_kept;
    cv::bitwise_and(mask, outside, outside_kept);
    EXPECT_EQ(cv::countNonZero(outside_kept), cv::countNonZero(outside));
  }
}

TEST(OccluderBankTest, ALayerCountsOutWhatLiesNearerThanItsOwnBoundWithinItsReach) {
  PreparedRegion region = FrameWithABoxInFront(0);
  const cv::Rect near_box = cv::Rect(200, 160, 120, 80) - region.region_px.tl();
  const cv::Rect second_box = cv::Rect(400, 300, 60, 50) - region.region_px.tl();
  region.depth_levels_mm.front()(second_box).setTo(803.0f);  // nearer than 807, not than 800
  const LayerReach whole = Layer(900.0, Everywhere(region));
  const LayerReach near_only =
      Layer(900.0, cv::Rect(near_box.tl() - cv::Point(10, 10), near_box.br() + cv::Point(10, 10)));
  const LayerReach clear = Layer(900.0, cv::Rect(500, 20, 80, 60));  // only background there
  const OccluderBank bank(region, std::vector<LayerReach>{whole});
  const Occluders* shared = bank.Find(800);
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(cv::countNonZero(shared->masks.front()), near_box.area());

  const std::optional<Occluders> layer = bank.ForLayer(whole);
  ASSERT_TRUE(layer.has_value());
  EXPECT_EQ(layer->ranked, shared->ranked);  // ranked on the shared copy, none made
  const cv::Mat& mask = layer->masks.front();
  EXPECT_EQ(cv::countNonZero(mask), near_box.area() + second_box.area());
  EXPECT_EQ(cv::countNonZero(mask(second_box)), second_box.area());

  const std::optional<Occluders> near_layer = bank.ForLayer(near_only);
  ASSERT_TRUE(near_layer.has_value());
  EXPECT_EQ(cv::countNonZero(near_layer->masks.front()), near_box.area());
  EXPECT_FALSE(bank.ForLayer(clear).has_value());  // nothing in front within its reach
  EXPECT_FALSE(bank.ForLayer(Layer(1200.0, near_only.reach_px)).has_value());  // 1100: not built
}

TEST(OccluderBankTest, BuildsOnlyTheEntriesOfLayersWithSomethingInFront) {
  const PreparedRegion region = FrameWithABoxInFront(0);
  const LayerReach clear = Layer(900.0, cv::Rect(500, 20, 80, 60));
  const OccluderBank bank(region, std::vector<LayerReach>{clear});
  EXPECT_EQ(bank.Find(800), nullptr);
  EXPECT_FALSE(bank.ForLayer(clear).has_value());
}

TEST(OccluderBankTest, WithoutDepthNothingIsAnOccluder) {
  cv::Mat color(120, 160, CV_8UC3, cv::Scalar(90, 120, 150));
  const PreparedRegion region = PrepareSceneRegion(color, cv::Mat(), test::RoundedKinectCamera(),
                                                   FeatureOptions(), cv::Rect(0, 0, 160, 120));
  const LayerReach layer = Layer(900.0, cv::Rect(0, 0, 160, 120));
  const OccluderBank bank(region, std::vector<LayerReach>{layer});
  EXPECT_EQ(bank.Find(800), nullptr);
  EXPECT_FALSE(bank.ForLayer(layer).has_value());
}

}  // namespace
}  // namespace layermod
