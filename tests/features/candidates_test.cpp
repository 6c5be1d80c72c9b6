// SPDX-License-Identifier: MIT
#include "features/candidates.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <map>
#include <opencv2/imgproc.hpp>

#include "features/quantize.h"
#include "features/synthetic_views.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(ColorGradientCandidatesTest, ThinToTheEdgeCentreLineInsideTheRegion) {
  // A vertical step edge between columns 19 and 20: the blurred gradient is strong over several
  // columns, candidates only on its ridge.
  cv::Mat image(40, 40, CV_8UC3, cv::Scalar::all(0));
  image.colRange(20, 40).setTo(cv::Scalar(200, 200, 200));
  const cv::Mat everywhere(image.size(), CV_8U, cv::Scalar(255));
  const auto candidates = ColorGradientCandidates(image, everywhere, {100, 50}, 10.0f, 55.0f);
  ASSERT_FALSE(candidates.empty());
  std::map<int, int> per_column;
  for (const FeatureCandidate& c : candidates) {
    ++per_column[c.x - 100];
    EXPECT_EQ(c.label, 0);  // horizontal gradient
    EXPECT_GT(c.score, 55.0f);
  }
  EXPECT_LE(per_column.size(), 2u);  // the two equal pixels either side of the step
  EXPECT_TRUE(per_column.count(19) + per_column.count(20) == per_column.size());

  cv::Mat cmp;
  QuantizeColorGradients(image, 10.0f, &cmp);
  EXPECT_GT(cv::countNonZero(cmp > 55.0f), 4 * 40);  // the band NMS thinned

  cv::Mat top_half = cv::Mat::zeros(image.size(), CV_8U);
  top_half.rowRange(0, 20).setTo(255);
  for (const FeatureCandidate& c : ColorGradientCandidates(image, top_half, {0, 0}, 10, 55)) {
    EXPECT_LT(c.y, 20);
  }
  EXPECT_THROW(ColorGradientCandidates(image, cv::Mat(3, 3, CV_8U), {0, 0}, 10, 55), Error);
}

TEST(LabelBorderDistanceTest, DistanceToLabelChangesAndInteriorBorder) {
  // Left half label 0, right half label 2, all interior: distance grows away from the seam.
  cv::Mat quantized(20, 30, CV_8U, cv::Scalar(1 << 0));
  quantized.colRange(15, 30).setTo(1 << 2);
  const cv::Mat interior(quantized.size(), CV_8U, cv::Scalar(255));
  const cv::Mat distance = LabelBorderDistance(quantized, interior);
  ASSERT_EQ(distance.type(), CV_32F);
  EXPECT_FLOAT_EQ(distance.at<float>(10, 14), 0.0f);  // differs from its right neighbour
  EXPECT_FLOAT_EQ(distance.at<float>(10, 15), 0.0f);
  EXPECT_FLOAT_EQ(distance.at<float>(10, 11), 3.0f);
  EXPECT_FLOAT_EQ(distance.at<float>(10, 19), 4.0f);
  // Outside the interior, and beside it, the distance is 0 too.
  cv::Mat small_interior = cv::Mat::zeros(quantized.size(), CV_8U);
  small_interior(cv::Rect(2, 2, 8, 16)).setTo(255);
  const cv::Mat clipped = LabelBorderDistance(quantized, small_interior);
  EXPECT_FLOAT_EQ(clipped.at<float>(10, 0), 0.0f);
  EXPECT_FLOAT_EQ(clipped.at<float>(10, 2), 1.0f);
  EXPECT_FLOAT_EQ(clipped.at<float>(10, 5), 4.0f);
}

TEST(DepthNormalCandidatesTest, EvenPixelsInsideAwayFromRidges) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Rect roi(301, 171, 150, 150);
  const RenderedView view = test::PyramidView(roi, {376, 246}, 55, 800.0f, 60.0f);
  cv::Mat interior;
  cv::erode(view.mask, interior, cv::Mat(), cv::Point(-1, -1), 2);
  const auto candidates = DepthNormalCandidates(view.depth_mm, interior, camera, roi.tl(), 50.0f,
                                                NormalFrame::kCamera, 63);
  ASSERT_GT(candidates.size(), 1000u);
  for (const FeatureCandidate& c : candidates) {
    ASSERT_EQ(c.x % 2, 0);
    ASSERT_EQ(c.y % 2, 0);
    ASSERT_NE(interior.at<std::uint8_t>(c.y - roi.y, c.x - roi.x), 0);
    EXPECT_GE(c.score, 2.0f);  // plenty of stable pixels: none near a label border
    const int du = c.x - 376, dv = c.y - 246;
    EXPECT_GT(std::abs(std::abs(du) - std::abs(dv)), 1);  // not on a ridge between faces
  }
  // Asking for more than the stable pixels keeps the unstable ones too.
  const auto all = DepthNormalCandidates(view.depth_mm, interior, camera, roi.tl(), 50.0f,
                                         NormalFrame::kCamera, 100000);
  EXPECT_GT(all.size(), candidates.size());
}

TEST(DepthNormalCandidatesTest, NothingWithoutInteriorOrDepth) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Mat depth(30, 30, CV_32F, cv::Scalar(700.0f));
  EXPECT_TRUE(DepthNormalCandidates(depth, cv::Mat::zeros(30, 30, CV_8U), camera, {0, 0}, 50.0f,
                                    NormalFrame::kCamera, 10)
                  .empty());
  EXPECT_TRUE(DepthNormalCandidates(cv::Mat::zeros(30, 30, CV_32F),
                                    cv::Mat(30, 30, CV_8U, cv::Scalar(255)), camera, {0, 0}, 50.0f,
                                    NormalFrame::kCamera, 10)
                  .empty());
  EXPECT_THROW(DepthNormalCandidates(depth, cv::Mat(3, 3, CV_8U), camera, {0, 0}, 50.0f,
                                     NormalFrame::kCamera, 10),
               Error);
}

}  // namespace
}  // namespace layermod
