// SPDX-License-Identifier: MIT
#include "pipeline/scene_preparation.h"
#include "support/test_cameras.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace layermod {
namespace {

// A colour image with smooth blobs (gradients everywhere) and a tilted, bumpy depth surface.
struct Frame {
  cv::Mat color;
  cv::Mat depth_mm;
};

Frame RandomFrame(cv::RNG& rng) {
  Frame frame;
  frame.color = cv::Mat(480, 640, CV_8UC3);
  rng.fill(frame.color, cv::RNG::UNIFORM, 0, 255);
  cv::GaussianBlur(frame.color, frame.color, cv::Size(0, 0), 3.0);
  frame.depth_mm = cv::Mat(480, 640, CV_32F);
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      frame.depth_mm.at<float>(y, x) = static_cast<float>(
          800.0 + 0.3 * x + 0.2 * y + 20.0 * std::sin(x / 17.0) * std::cos(y / 23.0));
    }
  }
  frame.depth_mm(cv::Rect(300, 200, 30, 20)).setTo(0.0f);  // a hole
  return frame;
}

TEST(ScenePreparationTest, ARegionIsAlignedAndMatchesTheWholeImageAwayFromItsBorder) {
  cv::RNG rng(71);
  const Frame frame = RandomFrame(rng);
  const FeatureOptions features;
  const PreparedScene whole =
      PrepareScene(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features);
  const cv::Rect asked(203, 141, 190, 133);
  const PreparedRegion region =
      PrepareSceneRegion(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features, asked);
  const int align = RegionAlignmentPx(features);
  EXPECT_EQ(align, features.spread_px.back() << (features.pyramid_levels - 1));
  EXPECT_EQ(region.region_px.x % align, 0);
  EXPECT_EQ(region.region_px.y % align, 0);
  EXPECT_EQ((region.region_px & asked), asked);  // grown, never cut
  ASSERT_EQ(region.scene.LevelCount(), whole.LevelCount());
  constexpr int kBorderPx = 8;  // image filtering may differ this close to the region's edge
  for (int level = 0; level < whole.LevelCount(); ++level) {
    const int scale = 1 << level;
    const cv::Rect inner(kBorderPx, kBorderPx, region.region_px.width / scale - 2 * kBorderPx,
                         region.region_px.height / scale - 2 * kBorderPx);
    const cv::Rect in_whole = inner + region.region_px.tl() / scale;
    for (int modality = 0; modality < kModalityCount; ++modality) {
      const cv::Mat& part = region.scene.Level(level).quantized[modality];
      const cv::Mat& full = whole.Level(level).quantized[modality];
      ASSERT_FALSE(part.empty());
      // OpenCV's Gaussian blur rounds some pixels of a sub-image one grey level differently
      // from the whole image's (checked: at most 1), which flips a rare gradient label.
      const int differing = cv::countNonZero(part(inner) != full(in_whole));
      EXPECT_LE(differing, static_cast<int>(inner.area() / 1000))
          << "level " << level << ", modality " << modality;
      if (modality == ModalityIndex(Modality::kDepthNormal)) {
        EXPECT_EQ(differing, 0);
      }
    }
  }
}

TEST(ScenePreparationTest, RegionsAreClippedToTheImage) {
  cv::RNG rng(72);
  const Frame frame = RandomFrame(rng);
  const FeatureOptions features;
  const PreparedRegion corner =
      PrepareSceneRegion(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features,
                         cv::Rect(600, 450, 100, 100));
  EXPECT_EQ(corner.region_px.br(), cv::Point(640, 480));
  const PreparedRegion outside =
      PrepareSceneRegion(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features,
                         cv::Rect(700, 500, 10, 10));
  EXPECT_TRUE(outside.region_px.empty());
  EXPECT_EQ(outside.scene.LevelCount(), 0);
}

TEST(ScenePreparationTest, APaddedRegionReachesPastTheImageWithoutLabelsThere) {
  cv::RNG rng(73);
  const Frame frame = RandomFrame(rng);
  const FeatureOptions features;
  const int align = RegionAlignmentPx(features);
  const PreparedRegion padded =
      PrepareSceneRegion(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features,
                         cv::Rect(-70, 400, 200, 200), SimdPath::kAuto, 50);
  // 50 px rounded up to the alignment on each side, the region's corner aligned.
  const int reach = (50 + align - 1) / align * align;
  EXPECT_EQ(padded.region_px.x, -reach);
  EXPECT_EQ(padded.region_px.br().y, 480 + reach);
  EXPECT_EQ(padded.region_px.y % align, 0);
  ASSERT_EQ(padded.outside_image.size(), static_cast<std::size_t>(features.pyramid_levels));
  const cv::Point image_tl = -padded.region_px.tl();
  for (int level = 0; level < padded.scene.LevelCount(); ++level) {
    const cv::Mat& outside = padded.outside_image[static_cast<std::size_t>(level)];
    ASSERT_EQ(outside.size(), padded.scene.Level(level).size_px);
    const int scale = 1 << level;
    // The column left of the image's first one and the row below its last one are padding, the
    // image's own first column and last row are not.
    const int first_x = image_tl.x / scale;
    const int last_y = (image_tl.y + 480) / scale - 1;
    EXPECT_NE(outside.at<std::uint8_t>(last_y - 2, first_x - 1), 0) << "level " << level;
    EXPECT_EQ(outside.at<std::uint8_t>(last_y - 2, first_x), 0) << "level " << level;
    EXPECT_NE(outside.at<std::uint8_t>(last_y + 1, first_x + 2), 0) << "level " << level;
    EXPECT_EQ(outside.at<std::uint8_t>(last_y, first_x + 2), 0) << "level " << level;
    for (int modality = 0; modality < kModalityCount; ++modality) {
      const cv::Mat& labels = padded.scene.Level(level).quantized[modality];
      EXPECT_EQ(cv::countNonZero(labels & outside), 0) << "level " << level;
      EXPECT_GT(cv::countNonZero(labels), 0) << "level " << level;
    }
  }
  EXPECT_EQ(cv::countNonZero(padded.gradient_labels & padded.outside_image.front()), 0);

  // Without padding the same region stops at the image, and has no padding masks.
  const PreparedRegion clipped =
      PrepareSceneRegion(frame.color, frame.depth_mm, test::RoundedKinectCamera(), features,
                         cv::Rect(-70, 400, 200, 200));
  EXPECT_EQ(clipped.region_px.tl(), cv::Point(0, 400 / align * align));
  EXPECT_TRUE(clipped.outside_image.empty());
}

}  // namespace
}  // namespace layermod
