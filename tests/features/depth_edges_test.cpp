// SPDX-License-Identifier: MIT
#include "features/depth_edges.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "util/error.h"

namespace layermod {
namespace {

// 30 x 40 map: columns < 20 at `left_mm`, the rest at `right_mm`.
cv::Mat StepDepth(float left_mm, float right_mm) {
  cv::Mat depth(30, 40, CV_32F, cv::Scalar(right_mm));
  depth.colRange(0, 20).setTo(left_mm);
  return depth;
}

TEST(DepthEdgeMaskTest, LargeStepIsAnEdgeOnBothSides) {
  const cv::Mat edges = DepthEdgeMask(StepDepth(800.0f, 900.0f), 30.0f);
  ASSERT_EQ(edges.type(), CV_8U);
  EXPECT_EQ(cv::countNonZero(edges.col(19)), 30);
  EXPECT_EQ(cv::countNonZero(edges.col(20)), 30);
  EXPECT_EQ(cv::countNonZero(edges), 60);
  EXPECT_EQ(CountDepthEdges(StepDepth(800.0f, 900.0f), 30.0f), 60);
}

TEST(DepthEdgeMaskTest, StepMeasuresItsHeightInMillimetres) {
  // A step of D mm gives a magnitude of D: it is an edge just below D, not at D.
  EXPECT_GT(CountDepthEdges(StepDepth(800.0f, 840.0f), 39.5f), 0);
  EXPECT_EQ(CountDepthEdges(StepDepth(800.0f, 840.0f), 40.5f), 0);
}

TEST(DepthEdgeMaskTest, SmallStepIsNotAnEdge) {
  EXPECT_EQ(CountDepthEdges(StepDepth(800.0f, 805.0f), 30.0f), 0);
}

TEST(DepthEdgeMaskTest, SmoothSlopeIsNotAnEdge) {
  // 5 mm per pixel (a surface at about 70 deg at 1 m) measures 2 x 5 = 10 mm.
  cv::Mat slope(30, 40, CV_32F);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) slope.at<float>(y, x) = 700.0f + 5.0f * x + 3.0f * y;
  }
  EXPECT_EQ(CountDepthEdges(slope, 30.0f), 0);
}

TEST(DepthEdgeMaskTest, InvalidDepthIsNeverNear) {
  // Object at 800 mm beside missing depth (0), NaN and inf: no edge anywhere.
  cv::Mat depth = StepDepth(800.0f, 0.0f);
  depth.at<float>(5, 5) = std::nanf("");
  depth.at<float>(10, 5) = std::numeric_limits<float>::infinity();
  depth.at<float>(15, 5) = -300.0f;
  EXPECT_EQ(CountDepthEdges(depth, 30.0f), 0);
  // A real step next to an invalid pixel: only windows free of invalid pixels count.
  cv::Mat step = StepDepth(800.0f, 900.0f);
  step.at<float>(10, 20) = 0.0f;
  const cv::Mat edges = DepthEdgeMask(step, 30.0f);
  EXPECT_EQ(edges.at<std::uint8_t>(5, 19), 255);
  EXPECT_EQ(edges.at<std::uint8_t>(10, 19), 0);
  EXPECT_EQ(cv::countNonZero(edges), 60 - 6);  // rows 9..11 of columns 19 and 20
}

TEST(DepthEdgeMaskTest, AnySizeAndBadInput) {
  EXPECT_EQ(CountDepthEdges(cv::Mat(0, 0, CV_32F), 30.0f), 0);
  EXPECT_EQ(CountDepthEdges(cv::Mat(1, 1, CV_32F, cv::Scalar(800.0f)), 30.0f), 0);
  cv::Mat two(1, 2, CV_32F);
  two.at<float>(0, 0) = 800.0f;
  two.at<float>(0, 1) = 1000.0f;
  EXPECT_EQ(CountDepthEdges(two, 30.0f), 2);
  EXPECT_THROW(DepthEdgeMask(cv::Mat(3, 3, CV_16U), 30.0f), Error);
  EXPECT_THROW(DepthEdgeMask(cv::Mat(3, 3, CV_32F), 0.0f), Error);
  EXPECT_THROW(DepthEdgeMask(cv::Mat(3, 3, CV_32F), std::nanf("")), Error);
}

// A sensor hole 4 px wide along the step, as real sensors leave at discontinuities.
cv::Mat StepWithHole() {
  cv::Mat depth = StepDepth(800.0f, 900.0f);
  depth.colRange(18, 22).setTo(0.0f);
  depth.at<float>(5, 10) = std::numeric_limits<float>::quiet_NaN();
  return depth;
}

TEST(FillDepthHolesFromFarTest, HoleAtAStepTakesTheFarSide) {
  const cv::Mat filled = FillDepthHolesFromFar(StepWithHole(), 8);
  for (int col = 18; col < 22; ++col) EXPECT_EQ(filled.at<float>(10, col), 900.0f) << col;
  EXPECT_EQ(filled.at<float>(5, 10), 800.0f);  // a NaN inside the near side: its neighbours
  EXPECT_EQ(filled.at<float>(10, 5), 800.0f);  // valid depth is untouched
  // The step is an edge again once the hole is filled; without filling the hole hides it.
  EXPECT_EQ(cv::countNonZero(DepthEdgeMask(StepWithHole(), 30.0f)), 0);
  EXPECT_GT(cv::countNonZero(DepthEdgeMask(filled, 30.0f)), 0);
}

TEST(FillDepthHolesFromFarTest, HolesWiderThanTheGapStayInvalid) {
  cv::Mat depth(30, 40, CV_32F, cv::Scalar(700.0f));
  depth.colRange(5, 35).setTo(0.0f);  // 30 px wide
  const cv::Mat filled = FillDepthHolesFromFar(depth, 4);
  EXPECT_EQ(filled.at<float>(10, 20), 0.0f);
  EXPECT_EQ(filled.at<float>(10, 5), 700.0f);
  EXPECT_EQ(cv::countNonZero(FillDepthHolesFromFar(cv::Mat::zeros(8, 8, CV_32F), 8)), 0);
  EXPECT_THROW(FillDepthHolesFromFar(cv::Mat::zeros(8, 8, CV_16U), 8), Error);
  EXPECT_THROW(FillDepthHolesFromFar(depth, -1), Error);
}

}  // namespace
}  // namespace layermod
