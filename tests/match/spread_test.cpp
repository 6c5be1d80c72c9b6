// SPDX-License-Identifier: MIT
#include "match/spread.h"

#include <gtest/gtest.h>

#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

bool Identical(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::countNonZero(a != b) == 0;
}

TEST(SpreadTest, AgreesWithNaiveReferenceOnOddSizes) {
  cv::RNG rng(7);
  for (const cv::Size size :
       {cv::Size(97, 61), cv::Size(640, 480), cv::Size(1, 1), cv::Size(3, 200), cv::Size(200, 2)}) {
    const cv::Mat quantized = test::RandomQuantized(size, 0.2, rng);
    for (int t : {1, 2, 4, 5, 8}) {
      EXPECT_TRUE(Identical(SpreadOrientations(quantized, t), test::NaiveSpread(quantized, t)))
          << size << " T=" << t;
    }
  }
}

TEST(SpreadTest, OneBitReachesTheBlockAboveAndLeft) {
  cv::Mat quantized = cv::Mat::zeros(20, 30, CV_8UC1);
  quantized.at<std::uint8_t>(10, 12) = 1 << 3;
  const cv::Mat spread = SpreadOrientations(quantized, 3);
  EXPECT_EQ(cv::countNonZero(spread), 9);
  EXPECT_EQ(spread.at<std::uint8_t>(8, 10), 1 << 3);
  EXPECT_EQ(spread.at<std::uint8_t>(10, 12), 1 << 3);
  EXPECT_EQ(spread.at<std::uint8_t>(11, 12), 0);
  EXPECT_EQ(spread.at<std::uint8_t>(10, 13), 0);
}

TEST(SpreadTest, SpreadOneIsIdentityAndInputIsUntouched) {
  cv::RNG rng(8);
  const cv::Mat quantized = test::RandomQuantized({41, 17}, 0.3, rng);
  const cv::Mat copy = quantized.clone();
  EXPECT_TRUE(Identical(SpreadOrientations(quantized, 1), quantized));
  SpreadOrientations(quantized, 5);
  EXPECT_TRUE(Identical(quantized, copy));
}

TEST(SpreadTest, WorksOnRegionsOfInterest) {
  cv::RNG rng(9);
  const cv::Mat big = test::RandomQuantized({80, 60}, 0.2, rng);
  const cv::Mat roi = big(cv::Rect(3, 5, 41, 33));
  EXPECT_TRUE(Identical(SpreadOrientations(roi, 4), test::NaiveSpread(roi.clone(), 4)));
}

TEST(SpreadTest, EmptyInEmptyOutAndBadArgumentsThrow) {
  EXPECT_TRUE(SpreadOrientations(cv::Mat(), 5).empty());
  const cv::Mat quantized = cv::Mat::zeros(4, 4, CV_8UC1);
  EXPECT_THROW(SpreadOrientations(quantized, 0), Error);
  EXPECT_THROW(SpreadOrientations(quantized, kMaxSpreadPx + 1), Error);
  EXPECT_THROW(SpreadOrientations(cv::Mat::zeros(4, 4, CV_16UC1), 2), Error);
}

}  // namespace
}  // namespace layermod
