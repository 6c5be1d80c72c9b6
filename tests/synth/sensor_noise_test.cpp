// SPDX-License-Identifier: MIT
#include "synth/sensor_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "synth_fixtures.h"

namespace layermod {
namespace {

const PinholeCamera kCamera = test::SmallCamera();

TEST(SensorNoiseTest, AxialSigmaFollowsNguyen) {
  const SensorNoiseOptions options;
  EXPECT_DOUBLE_EQ(AxialNoiseSigmaMm(400.0, options), 1.2);
  EXPECT_NEAR(AxialNoiseSigmaMm(1000.0, options), 1.2 + 1.9 * 0.36, 1e-12);
  EXPECT_NEAR(AxialNoiseSigmaMm(1400.0, options), 3.1, 1e-12);
}

TEST(SensorNoiseTest, DisparityQuantisationStepGrowsWithDepthSquared) {
  const SensorNoiseOptions options;
  const double focal = 572.0;
  const double level = QuantizeDepthMm(1000.0, focal, options);
  EXPECT_DOUBLE_EQ(QuantizeDepthMm(level, focal, options), level);  // levels are fixed points
  // The next level: one 1/8-pixel disparity step nearer.
  const double disparity = focal * options.baseline_mm / level;
  const double next = focal * options.baseline_mm / (disparity + 1.0 / options.disparity_subpixel);
  const double expected_step = 1000.0 * 1000.0 / (focal * options.baseline_mm * 8.0);
  EXPECT_NEAR(level - next, expected_step, 0.05 * expected_step);
  EXPECT_LE(std::abs(level - 1000.0), 0.5 * expected_step + 1e-9);
}

TEST(SensorNoiseTest, FlatPlaneAtOneMetreHasTheModelledNoise) {
  // The Kinect's VGA focal length: its disparity steps are finer than the noise at 1 m.
  const PinholeCamera kinect = kCamera.Scaled(2.0);
  const cv::Mat clean(kinect.height, kinect.width, CV_32F, cv::Scalar(1000.0f));
  SensorNoiseOptions options;
  options.holes_max = 0;
  std::mt19937_64 rng(11);
  const cv::Mat depth = ApplyDepthSensorModel(clean, kinect, options, rng);
  cv::Scalar mean;
  cv::Scalar sigma;
  cv::meanStdDev(depth - clean, mean, sigma, depth > 0.0f);
  const double model = AxialNoiseSigmaMm(1000.0, options);
  EXPECT_NEAR(mean[0], 0.0, 0.3);
  EXPECT_GT(sigma[0], 0.5 * model);
  EXPECT_LT(sigma[0], 1.5 * model);
  EXPECT_EQ(cv::countNonZero(depth == 0.0f), 0);  // no edges, no holes: nothing missing
}

TEST(SensorNoiseTest, OutOfRangeDepthIsDropped) {
  cv::Mat clean(10, 10, CV_32F, cv::Scalar(300.0f));
  clean(cv::Rect(5, 0, 5, 10)).setTo(5000.0f);
  SensorNoiseOptions options;
  options.holes_max = 0;
  std::mt19937_64 rng(1);
  EXPECT_EQ(cv::countNonZero(ApplyDepthSensorModel(clean, kCamera, options, rng)), 0);
}

TEST(SensorNoiseTest, DepthIsLostOnlyInABandAtDiscontinuities) {
  cv::Mat clean(kCamera.height, kCamera.width, CV_32F, cv::Scalar(800.0f));
  clean(cv::Rect(160, 0, 160, kCamera.height)).setTo(1200.0f);
  SensorNoiseOptions options;
  options.holes_max = 0;
  for (int seed = 0; seed < 5; ++seed) {
    std::mt19937_64 rng(static_cast<unsigned>(seed));
    const cv::Mat depth = ApplyDepthSensorModel(clean, kCamera, options, rng);
    const cv::Mat missing = depth == 0.0f;
    const cv::Rect band(160 - options.edge_band_max_px, 0, 2 * options.edge_band_max_px,
                        kCamera.height);
    const int in_band = cv::countNonZero(missing(band));
    EXPECT_EQ(cv::countNonZero(missing), in_band);  // nothing lost away from the edge
    EXPECT_GT(in_band, kCamera.height / 4);         // about half of the band
    EXPECT_LT(in_band, 2 * options.edge_band_max_px * kCamera.height);
  }
}

TEST(SensorNoiseTest, HolesAreFewAndSmall) {
  const cv::Mat clean(kCamera.height, kCamera.width, CV_32F, cv::Scalar(900.0f));
  const SensorNoiseOptions options;
  for (int seed = 0; seed < 5; ++seed) {
    std::mt19937_64 rng(static_cast<unsigned>(seed));
    const cv::Mat depth = ApplyDepthSensorModel(clean, kCamera, options, rng);
    const double fraction = cv::countNonZero(depth == 0.0f) / static_cast<double>(depth.total());
    EXPECT_GT(fraction, 0.0);
    EXPECT_LT(fraction, 0.02);
  }
}

TEST(SensorNoiseTest, DeterministicAndSwitchable) {
  const cv::Mat clean(60, 80, CV_32F, cv::Scalar(1000.0f));
  SensorNoiseOptions options;
  std::mt19937_64 a(5);
  std::mt19937_64 b(5);
  EXPECT_EQ(cv::norm(ApplyDepthSensorModel(clean, kCamera, options, a),
                     ApplyDepthSensorModel(clean, kCamera, options, b), cv::NORM_INF),
            0.0);
  options.enabled = false;
  EXPECT_EQ(cv::norm(ApplyDepthSensorModel(clean, kCamera, options, a), clean, cv::NORM_INF), 0.0);
  const cv::Mat color(60, 80, CV_8UC3, cv::Scalar(10, 20, 30));
  EXPECT_EQ(cv::norm(ApplyColorSensorModel(color, options, a), color, cv::NORM_INF), 0.0);
}

TEST(SensorNoiseTest, ColourNoiseHasTheConfiguredSigma) {
  const cv::Mat color(120, 160, CV_8UC3, cv::Scalar::all(128));
  const SensorNoiseOptions options;
  std::mt19937_64 rng(3);
  const cv::Mat noisy = ApplyColorSensorModel(color, options, rng);
  cv::Scalar mean;
  cv::Scalar sigma;
  cv::meanStdDev(noisy.reshape(1), mean, sigma);
  EXPECT_NEAR(mean[0], 128.0, 0.5);
  EXPECT_NEAR(sigma[0], options.color_noise_sigma, 0.5);
}

}  // namespace
}  // namespace layermod
