// SPDX-License-Identifier: MIT
#include "synth/textures.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(TexturesTest, ListsImagesSortedAndRefusesEmptyFolders) {
  test::TempDir dir;
  const cv::Mat image(8, 8, CV_8UC3, cv::Scalar(1, 2, 3));
  cv::imwrite((dir / "b.png").string(), image);
  cv::imwrite((dir / "a.JPG").string(), image);
  std::ofstream(dir / "notes.txt") << "x";
  const auto images = ListBackgroundImages(dir.path());
  ASSERT_EQ(images.size(), 2u);
  EXPECT_EQ(images[0].filename(), "a.JPG");
  EXPECT_EQ(images[1].filename(), "b.png");
  fs::create_directories(dir / "empty");
  EXPECT_THROW(ListBackgroundImages(dir / "empty"), IoError);
  EXPECT_THROW(ListBackgroundImages(dir / "missing"), IoError);
}

TEST(TexturesTest, ProceduralTexturesAreDeterministicAndLookTheirPart) {
  std::mt19937_64 a(4);
  std::mt19937_64 b(4);
  const cv::Mat first = MakeProceduralTexture(SurfaceKind::kTable, a);
  EXPECT_EQ(first.type(), CV_8UC3);
  EXPECT_EQ(first.size(), cv::Size(kTextureSize, kTextureSize));
  EXPECT_EQ(cv::norm(first, MakeProceduralTexture(SurfaceKind::kTable, b), cv::NORM_INF), 0.0);
  for (int i = 0; i < 5; ++i) {
    const double floor = cv::mean(MakeProceduralTexture(SurfaceKind::kFloor, a))[1];
    const double wall = cv::mean(MakeProceduralTexture(SurfaceKind::kWall, a))[1];
    EXPECT_LT(floor, wall);  // dark floors, light walls
  }
}

TEST(TexturesTest, TableTextureIsACropOfAPhoto) {
  test::TempDir dir;
  cv::imwrite((dir / "photo.png").string(), cv::Mat(300, 400, CV_8UC3, cv::Scalar(10, 200, 30)));
  std::mt19937_64 rng(1);
  const cv::Mat texture = MakeTableTexture({dir / "photo.png"}, rng);
  EXPECT_EQ(texture.size(), cv::Size(kTextureSize, kTextureSize));
  EXPECT_EQ(texture.at<cv::Vec3b>(100, 100), cv::Vec3b(10, 200, 30));
  EXPECT_THROW(MakeTableTexture({dir / "missing.png"}, rng), IoError);
}

TEST(TexturesTest, SamplingTilesByMirroringAndStaysInTheMask) {
  // Left half black, right half white; isolated pixels sample level 0.
  cv::Mat texture(kTextureSize, kTextureSize, CV_8UC3, cv::Scalar::all(0));
  texture(cv::Rect(kTextureSize / 2, 0, kTextureSize / 2, kTextureSize))
      .setTo(cv::Scalar::all(255));
  const std::vector<float> xs = {100.0f, 400.0f, 612.0f, -100.0f, 1500.0f};
  const std::vector<int> expected = {0, 255, 255, 0, 255};  // 612 -> 411, -100 -> 99, 1500 -> 476
  cv::Mat plane_xy(1, 2 * static_cast<int>(xs.size()), CV_32FC2, cv::Scalar(0, 0));
  cv::Mat mask = cv::Mat::zeros(plane_xy.size(), CV_8U);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    plane_xy.at<cv::Vec2f>(0, 2 * static_cast<int>(i)) = cv::Vec2f(xs[i], 40.0f);
    mask.at<uchar>(0, 2 * static_cast<int>(i)) = 255;
  }
  TextureMapping mapping;
  mapping.mm_per_texel = 1.0;
  const cv::Mat color = SampleTexture(texture, plane_xy, mask, mapping);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const int column = 2 * static_cast<int>(i);
    EXPECT_EQ(color.at<cv::Vec3b>(0, column)[1], expected[i]) << "x = " << xs[i];
    EXPECT_EQ(color.at<cv::Vec3b>(0, column + 1), cv::Vec3b(0, 0, 0));  // outside the mask
  }
}

TEST(TexturesTest, FarAwayTexelsAreAveragedNotAliased) {
  // A fine checkerboard seen with 16 texels per pixel must come out mid-grey.
  cv::Mat texture(kTextureSize, kTextureSize, CV_8UC3);
  for (int y = 0; y < kTextureSize; ++y) {
    for (int x = 0; x < kTextureSize; ++x) {
      texture.at<cv::Vec3b>(y, x) = cv::Vec3b::all((x + y) % 2 == 0 ? 255 : 0);
    }
  }
  cv::Mat plane_xy(20, 20, CV_32FC2);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 20; ++x) plane_xy.at<cv::Vec2f>(y, x) = cv::Vec2f(16.0f * x, 16.0f * y);
  }
  TextureMapping mapping;
  mapping.mm_per_texel = 1.0;
  const cv::Mat color =
      SampleTexture(texture, plane_xy, cv::Mat(20, 20, CV_8U, cv::Scalar(255)), mapping);
  double low = 0.0;
  double high = 0.0;
  cv::minMaxLoc(color.reshape(1), &low, &high);
  EXPECT_GT(low, 100.0);
  EXPECT_LT(high, 155.0);
}

}  // namespace
}  // namespace layermod
