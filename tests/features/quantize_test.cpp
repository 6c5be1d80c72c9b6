// SPDX-License-Identifier: MIT
#include "features/quantize.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <set>

#include "features/synthetic_views.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kDegToRad = CV_PI / 180.0;

// A straight edge near the image centre whose gradient points at `gradient_deg` (image axes),
// anti-aliased over one pixel so that its staircase does not bend the local orientation.
cv::Mat EdgeImage(double gradient_deg, const cv::Vec3b& low, const cv::Vec3b& high,
                  cv::Size size = {41, 41}) {
  cv::Mat image(size, CV_8UC3);
  const double c = std::cos(gradient_deg * kDegToRad), s = std::sin(gradient_deg * kDegToRad);
  const int centre_x = size.width / 2, centre_y = size.height / 2;
  for (int y = 0; y < size.height; ++y) {
    for (int x = 0; x < size.width; ++x) {
      // A one-pixel ramp, half a pixel beside the centre pixel along the gradient.
      const double t = std::clamp((x - centre_x) * c + (y - centre_y) * s, 0.0, 1.0);
      cv::Vec3b value;
      for (int i = 0; i < 3; ++i) {
        value[i] = cv::saturate_cast<uchar>(low[i] + t * (high[i] - low[i]));
      }
      image.at<cv::Vec3b>(y, x) = value;
    }
  }
  return image;
}

bool IsZeroOrSingleBit(std::uint8_t value) { return (value & (value - 1)) == 0; }

int CentreLabel(const cv::Mat& quantized) {
  return LabelOfBit(quantized.at<std::uint8_t>(quantized.rows / 2, quantized.cols / 2));
}

TEST(QuantizeColorGradientsTest, EdgeAtEveryBinCentreGetsItsLabelWhateverTheSign) {
  std::set<int> labels;
  for (int k = 0; k < 16; ++k) {
    const double angle_deg = k * 22.5;  // k and k + 8: the same edge with reversed contrast
    const cv::Mat quantized =
        QuantizeColorGradients(EdgeImage(angle_deg, {20, 20, 20}, {20, 20, 220}), 10.0f);
    EXPECT_EQ(CentreLabel(quantized), k % 8) << "gradient at " << angle_deg << " deg";
    labels.insert(CentreLabel(quantized));
  }
  EXPECT_EQ(labels.size(), 8u);
}

TEST(QuantizeColorGradientsTest, AnglesInsideABinStayInIt) {
  for (int k = 0; k < 8; ++k) {
    for (double offset_deg : {-8.0, 8.0}) {
      const double angle_deg = k * 22.5 + offset_deg;
      const cv::Mat quantized =
          QuantizeColorGradients(EdgeImage(angle_deg, {0, 0, 0}, {200, 200, 200}, {61, 61}), 10.0f);
      EXPECT_EQ(CentreLabel(quantized), k) << "gradient at " << angle_deg << " deg";
    }
  }
}

TEST(QuantizeColorGradientsTest, StrongestChannelDecides) {
  // Green has a strong vertical edge, red a weaker horizontal one.
  cv::Mat image(41, 41, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < 41; ++y) {
    for (int x = 0; x < 41; ++x) {
      image.at<cv::Vec3b>(y, x)[1] = x > 20 ? 200 : 0;
      image.at<cv::Vec3b>(y, x)[2] = y > 20 ? 60 : 0;
    }
  }
  cv::Mat magnitude;
  const cv::Mat quantized = QuantizeColorGradients(image, 10.0f, &magnitude);
  EXPECT_EQ(LabelOfBit(quantized.at<std::uint8_t>(20, 20)), 0);  // green wins over red
  EXPECT_EQ(LabelOfBit(quantized.at<std::uint8_t>(20, 5)), 4);   // red alone there: vertical
  EXPECT_GT(magnitude.at<float>(20, 20), 300.0f);
}

TEST(QuantizeColorGradientsTest, MagnitudeIsAboutTwiceTheContrast) {
  cv::Mat magnitude;
  QuantizeColorGradients(EdgeImage(0.0, {0, 0, 0}, {100, 100, 100}), 10.0f, &magnitude);
  ASSERT_EQ(magnitude.type(), CV_32F);
  double max_magnitude = 0.0;
  cv::minMaxLoc(magnitude, nullptr, &max_magnitude);
  EXPECT_NEAR(max_magnitude, 200.0, 20.0);
}

TEST(QuantizeColorGradientsTest, WeakGradientsHaveNoLabel) {
  const cv::Mat faint = EdgeImage(45.0, {100, 100, 100}, {104, 104, 104});  // magnitude ~8
  EXPECT_EQ(cv::countNonZero(QuantizeColorGradients(faint, 10.0f)), 0);
  EXPECT_GT(cv::countNonZero(QuantizeColorGradients(faint, 5.0f)), 0);
}

TEST(QuantizeColorGradientsTest, MajorityVoteRemovesIsolatedNoise) {
  // Salt noise: each dot's blurred gradients point in all directions around it, so few 3x3
  // neighbourhoods agree; a straight edge keeps nearly all its labels.
  cv::Mat noise(80, 80, CV_8UC3, cv::Scalar::all(100));
  for (int y = 4; y < 80; y += 9) {
    for (int x = 4; x < 80; x += 9) noise.at<cv::Vec3b>(y, x) = {255, 255, 255};
  }
  cv::Mat magnitude;
  const cv::Mat noisy = QuantizeColorGradients(noise, 10.0f, &magnitude);
  const int strong = cv::countNonZero(magnitude > 10.0f);
  ASSERT_GT(strong, 500);
  EXPECT_LT(cv::countNonZero(noisy), strong / 2);

  const cv::Mat edge =
      QuantizeColorGradients(EdgeImage(90.0, {0, 0, 0}, {90, 90, 90}), 10.0f, &magnitude);
  EXPECT_GT(cv::countNonZero(edge), 0.95 * cv::countNonZero(magnitude > 10.0f));
}

TEST(QuantizeColorGradientsTest, OutputIsZeroOrOneBitOnAnyImage) {
  cv::Mat random(37, 53, CV_8UC3);
  cv::randu(random, cv::Scalar::all(0), cv::Scalar::all(256));
  const cv::Mat quantized = QuantizeColorGradients(random, 10.0f);
  ASSERT_EQ(quantized.type(), CV_8U);
  ASSERT_EQ(quantized.size(), random.size());
  EXPECT_GT(cv::countNonZero(quantized), 0);
  for (int y = 0; y < quantized.rows; ++y) {
    for (int x = 0; x < quantized.cols; ++x) {
      EXPECT_TRUE(IsZeroOrSingleBit(quantized.at<std::uint8_t>(y, x)));
    }
  }
}

TEST(QuantizeColorGradientsTest, TinyAndEmptyImagesWork) {
  for (const cv::Size size : {cv::Size(0, 0), cv::Size(1, 1), cv::Size(2, 3), cv::Size(1, 40)}) {
    cv::Mat image(size, CV_8UC3, cv::Scalar(10, 200, 30));
    cv::Mat magnitude;
    const cv::Mat quantized = QuantizeColorGradients(image, 10.0f, &magnitude);
    EXPECT_EQ(quantized.size(), size);
    EXPECT_EQ(magnitude.size(), size);
    EXPECT_EQ(cv::countNonZero(quantized), 0);
  }
  EXPECT_THROW(QuantizeColorGradients(cv::Mat(4, 4, CV_8U), 10.0f), Error);
}

// ---- normal quantization ----

cv::Vec3f TiltedNormal(double direction_deg, double tilt_deg) {
  const double s = std::sin(tilt_deg * kDegToRad);
  return {static_cast<float>(s * std::cos(direction_deg * kDegToRad)),
          static_cast<float>(s * std::sin(direction_deg * kDegToRad)),
          static_cast<float>(-std::cos(tilt_deg * kDegToRad))};
}

int NormalLabel(const cv::Vec3f& normal) {
  const cv::Mat quantized = QuantizeNormals(cv::Mat(1, 1, CV_32FC3, cv::Scalar(normal)));
  return LabelOfBit(quantized.at<std::uint8_t>(0, 0));
}

TEST(QuantizeNormalsTest, EightDirectionsGetEightDistinctLabels) {
  std::set<int> labels;
  for (int k = 0; k < 8; ++k) {
    for (double tilt_deg : {20.0, 45.0, 80.0}) {
      EXPECT_EQ(NormalLabel(TiltedNormal(k * 45.0, tilt_deg)), k);
      EXPECT_EQ(NormalLabel(TiltedNormal(k * 45.0 - 20.0, tilt_deg)), k);
      EXPECT_EQ(NormalLabel(TiltedNormal(k * 45.0 + 20.0, tilt_deg)), k);
    }
    labels.insert(NormalLabel(TiltedNormal(k * 45.0, 30.0)));
  }
  EXPECT_EQ(labels.size(), 8u);
}

TEST(QuantizeNormalsTest, FrontalNormalsShareOneLabel) {
  EXPECT_EQ(NormalLabel({0.0f, 0.0f, -1.0f}), kFrontalNormalLabel);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(NormalLabel(TiltedNormal(k * 45.0 + 10.0, 5.0)), kFrontalNormalLabel);
  }
  // Without the frontal cone the exact frontal normal still gets that label (tie-break).
  const cv::Mat frontal(1, 1, CV_32FC3, cv::Scalar(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(QuantizeNormals(frontal, 0.0f).at<std::uint8_t>(0, 0), 1 << kFrontalNormalLabel);
}

TEST(QuantizeNormalsTest, InvalidNormalsGetZero) {
  cv::Mat normals(1, 3, CV_32FC3);
  normals.at<cv::Vec3f>(0, 0) = {0.0f, 0.0f, 0.0f};
  normals.at<cv::Vec3f>(0, 1) = {std::nanf(""), 0.0f, -1.0f};
  normals.at<cv::Vec3f>(0, 2) = {std::numeric_limits<float>::infinity(), 0.0f, 0.0f};
  EXPECT_EQ(cv::countNonZero(QuantizeNormals(normals)), 0);
  EXPECT_THROW(QuantizeNormals(cv::Mat(2, 2, CV_32F)), Error);
}

TEST(QuantizeNormalsTest, TiltedPlaneGetsTheLabelOfItsDirection) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Rect roi(100, 100, 40, 40);
  // Surface facing the camera, leaning so its normal's (nx, ny) points at 90 deg (image down).
  const Eigen::Vector3d normal = Eigen::Vector3d(0.0, 0.6, -0.8).normalized();
  const cv::Mat depth = test::PlaneDepth(camera, roi, {-150.0, -100.0, 700.0}, normal);
  const cv::Mat quantized =
      QuantizeNormals(ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera));
  EXPECT_EQ(cv::countNonZero(quantized == (1 << 2)), roi.area());
}

}  // namespace
}  // namespace layermod
