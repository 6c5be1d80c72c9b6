// SPDX-License-Identifier: MIT
#include "scene/depth_mm.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

using ::testing::HasSubstr;

std::string ErrorOf(const cv::Mat& depth, const DepthScale& scale = {}) {
  try {
    DepthToMillimetres(depth, scale);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(DepthMmTest, SixteenBitIsScaledToMillimetres) {
  cv::Mat raw(2, 2, CV_16U, cv::Scalar(8000));
  raw.at<std::uint16_t>(0, 0) = 0;
  const cv::Mat mm = DepthToMillimetres(raw, DepthScale{0.1, 1.0});
  EXPECT_EQ(mm.type(), CV_32F);
  EXPECT_EQ(mm.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(mm.at<float>(1, 1), 800.0f);
}

TEST(DepthMmTest, FloatMetresAreScaledAndInvalidValuesBecomeZero) {
  cv::Mat metres(2, 2, CV_32F, cv::Scalar(0.8f));
  metres.at<float>(0, 0) = std::numeric_limits<float>::quiet_NaN();
  metres.at<float>(0, 1) = -std::numeric_limits<float>::infinity();
  metres.at<float>(1, 0) = -0.5f;
  const cv::Mat mm = DepthToMillimetres(metres, DepthScale{1.0, 1000.0});
  EXPECT_EQ(mm.at<float>(0, 0), 0.0f);
  EXPECT_EQ(mm.at<float>(0, 1), 0.0f);
  EXPECT_EQ(mm.at<float>(1, 0), 0.0f);
  EXPECT_NEAR(mm.at<float>(1, 1), 800.0f, 1e-3);
}

TEST(DepthMmTest, CleanFloatMillimetresAreNotCopied) {
  const cv::Mat depth(3, 3, CV_32F, cv::Scalar(750.0f));
  EXPECT_EQ(DepthToMillimetres(depth).data, depth.data);
}

TEST(DepthMmTest, DirtyFloatMillimetresAreCleanedInACopy) {
  cv::Mat depth(3, 3, CV_32F, cv::Scalar(750.0f));
  depth.at<float>(1, 1) = std::numeric_limits<float>::infinity();
  const cv::Mat mm = DepthToMillimetres(depth);
  EXPECT_NE(mm.data, depth.data);
  EXPECT_EQ(mm.at<float>(1, 1), 0.0f);
  EXPECT_TRUE(std::isinf(depth.at<float>(1, 1)));  // the caller's image is left alone
}

TEST(DepthMmTest, RefusesWhatIsNotADepthImage) {
  EXPECT_THAT(ErrorOf(cv::Mat()), HasSubstr("empty"));
  EXPECT_THAT(ErrorOf(cv::Mat(2, 2, CV_16UC3)), HasSubstr("1 channel, got 3"));
  EXPECT_THAT(ErrorOf(cv::Mat(2, 2, CV_8U, cv::Scalar(1))), HasSubstr("8-bit depth image"));
  EXPECT_THAT(ErrorOf(cv::Mat(2, 2, CV_64F, cv::Scalar(1))), HasSubstr("CV_64F"));
}

TEST(DepthMmTest, RefusesAScaleThatIsNotAPositiveNumber) {
  const cv::Mat raw(2, 2, CV_16U, cv::Scalar(800));
  EXPECT_THAT(ErrorOf(raw, DepthScale{0.0, 1.0}), HasSubstr("depth scale"));
  EXPECT_THAT(ErrorOf(raw, DepthScale{std::numeric_limits<double>::quiet_NaN(), 1.0}),
              HasSubstr("depth scale"));
  const cv::Mat mm(2, 2, CV_32F, cv::Scalar(800.0f));
  EXPECT_THAT(ErrorOf(mm, DepthScale{1.0, -1.0}), HasSubstr("depth scale"));
}

}  // namespace
}  // namespace layermod
