// SPDX-License-Identifier: MIT
#include "dataset/bop_images.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "bop_fixtures.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(BopImagesTest, DepthEncodingRoundsSaturatesAndDropsInvalid) {
  cv::Mat depth_mm(1, 5, CV_32F);
  depth_mm.at<float>(0) = 700.4f;
  depth_mm.at<float>(1) = 700.6f;
  depth_mm.at<float>(2) = 1e9f;
  depth_mm.at<float>(3) = -5.0f;
  depth_mm.at<float>(4) = std::numeric_limits<float>::quiet_NaN();
  const cv::Mat encoded = EncodeBopDepth(depth_mm, 1.0);
  ASSERT_EQ(encoded.type(), CV_16U);
  EXPECT_EQ(encoded.at<std::uint16_t>(0), 700);
  EXPECT_EQ(encoded.at<std::uint16_t>(1), 701);
  EXPECT_EQ(encoded.at<std::uint16_t>(2), 65535);
  EXPECT_EQ(encoded.at<std::uint16_t>(3), 0);
  EXPECT_EQ(encoded.at<std::uint16_t>(4), 0);
  EXPECT_EQ(EncodeBopDepth(depth_mm, 0.1).at<std::uint16_t>(0), 7004);
}

TEST(BopImagesTest, PngRoundTripAndGreyColourIsExpanded) {
  test::TempDir dir;
  cv::Mat depth(3, 4, CV_16U, cv::Scalar(1234));
  WritePngAtomically(dir / "d.png", depth);
  EXPECT_FLOAT_EQ(ReadBopDepth(dir / "d.png", 0.5).at<float>(2, 3), 617.0f);
  WritePngAtomically(dir / "g.png", cv::Mat(3, 4, CV_8U, cv::Scalar(9)));
  const cv::Mat color = ReadBopColor(dir / "g.png");
  EXPECT_EQ(color.type(), CV_8UC3);
  EXPECT_EQ(color.at<cv::Vec3b>(1, 1), cv::Vec3b(9, 9, 9));
}

TEST(BopImagesTest, WrongDepthFormatsAreRefused) {
  test::TempDir dir;
  WritePngAtomically(dir / "d8.png", cv::Mat(3, 4, CV_8U, cv::Scalar(9)));
  EXPECT_THROW(ReadBopDepth(dir / "d8.png", 1.0), FormatError);
  WritePngAtomically(dir / "rgb16.png", cv::Mat(3, 4, CV_16UC3, cv::Scalar(9, 9, 9)));
  EXPECT_THROW(ReadBopDepth(dir / "rgb16.png", 1.0), FormatError);
  EXPECT_THROW(ReadBopDepth(dir / "none.png", 1.0), IoError);
  test::WriteText(dir / "junk.png", "\x89PNG but no");
  EXPECT_THROW(ReadBopColor(dir / "junk.png"), IoError);
}

}  // namespace
}  // namespace layermod
