// SPDX-License-Identifier: MIT
#include "features/pyramid.h"

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "features/synthetic_views.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(PyramidTest, NearestKeepsEvenPixelsAndRoundsSizesUp) {
  cv::Mat depth(5, 7, CV_32F);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 7; ++x) depth.at<float>(y, x) = static_cast<float>(100 * y + x);
  }
  const cv::Mat down = DownsampleNearest(depth);
  ASSERT_EQ(down.size(), cv::Size(4, 3));
  ASSERT_EQ(down.type(), CV_32F);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) EXPECT_EQ(down.at<float>(y, x), 100.0f * 2 * y + 2 * x);
  }
  const cv::Mat mask(3, 3, CV_8U, cv::Scalar(255));
  EXPECT_EQ(cv::countNonZero(DownsampleNearest(mask)), 4);
  EXPECT_TRUE(DownsampleNearest(cv::Mat(0, 0, CV_32F)).empty());
}

TEST(PyramidTest, ColorDownsamplingHalvesTheSizeAndKeepsFlatColour) {
  const cv::Mat color(9, 10, CV_8UC3, cv::Scalar(10, 120, 230));
  const cv::Mat down = DownsampleColor(color);
  ASSERT_EQ(down.size(), cv::Size(5, 5));
  EXPECT_EQ(down.at<cv::Vec3b>(2, 3), cv::Vec3b(10, 120, 230));
  EXPECT_TRUE(DownsampleColor(cv::Mat()).empty());
}

TEST(PyramidTest, LevelCameraProjectsToHalfTheLevelZeroPixel) {
  const PinholeCamera camera = test::KinectCamera();
  const Eigen::Vector3d point(-120.0, 75.0, 830.0);
  for (int level : {1, 2, 3}) {
    const PinholeCamera scaled = PyramidLevelCamera(camera, level);
    const Eigen::Vector2d expected = camera.Project(point) / static_cast<double>(1 << level);
    EXPECT_NEAR((scaled.Project(point) - expected).norm(), 0.0, 1e-9);
  }
  EXPECT_EQ(PyramidLevelCamera(camera, 1).width, 320);
  EXPECT_EQ(PyramidLevelCamera(camera, 0), camera);
  EXPECT_THROW(PyramidLevelCamera(camera, -1), Error);
}

}  // namespace
}  // namespace layermod
