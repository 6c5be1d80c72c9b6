// SPDX-License-Identifier: MIT
#include "geometry/views.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/matchers.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(AngleRangeTest, ParsesAndEnumeratesInclusive) {
  const AngleRange range = AngleRange::Parse("-45:15:45", "roll");
  EXPECT_EQ(range.Values(), (std::vector<double>{-45, -30, -15, 0, 15, 30, 45}));
  EXPECT_EQ(AngleRange::Parse("0:15:345", "azimuth").Values().size(), 24u);
  EXPECT_EQ(AngleRange::Parse("10:10:10", "x").Values(), std::vector<double>{10});
}

TEST(AngleRangeTest, RejectsBadText) {
  EXPECT_THROW(AngleRange::Parse("0:15", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("0:0:90", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("0:-5:90", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("90:5:0", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("a:5:10", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("0:5:10:20", "azimuth"), Error);
  EXPECT_THROW(AngleRange::Parse("nan:5:10", "azimuth"), Error);
}

TEST(ViewsTest, GridCountIsProductOfRanges) {
  ViewSamplingOptions options;
  options.azimuth = {0, 15, 345};
  options.elevation = {0, 15, 75};
  options.roll = {-45, 15, 45};
  EXPECT_EQ(SampleViews(options).size(), 24u * 6u * 7u);
}

TEST(ViewsTest, CountViewsMatchesTheSampledViews) {
  ViewSamplingOptions grid;
  grid.azimuth = {0, 20, 340};
  grid.elevation = {15, 15, 75};
  grid.roll = {-20, 20, 20};
  EXPECT_EQ(CountViews(grid), SampleViews(grid).size());
  ViewSamplingOptions even = grid;
  even.even_spacing_deg = 7.5;
  EXPECT_EQ(CountViews(even), SampleViews(even).size());
  EXPECT_EQ(AngleRange({0, 0.1, 0.3}).Count(), 4u);  // inclusive despite rounding
}

TEST(ViewsTest, HugeGridsAreRefusedBeforeSampling) {
  ViewSamplingOptions options;
  options.azimuth = {0, 0.004, 359};
  options.elevation = {0, 0.001, 90};
  options.roll = {-45, 0.001, 45};
  EXPECT_EQ(CountViews(options), std::size_t{89751} * 90001 * 90001);
  try {
    SampleViews(options);
    FAIL() << "a grid of 7e14 views was sampled";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("use larger angle steps"));
  }
}

TEST(ViewsTest, EvenSamplingStaysInElevationRangeAndIsRoughlyUniform) {
  ViewSamplingOptions options;
  options.elevation = {0, 1, 90};
  options.roll = {0, 1, 0};
  options.even_spacing_deg = 10.0;
  const auto views = SampleViews(options);
  // Hemisphere area 2*pi over (10 deg)^2 cells -> about 206 directions.
  EXPECT_GT(views.size(), 180u);
  EXPECT_LT(views.size(), 230u);
  int near_pole = 0;
  for (const auto& view : views) {
    EXPECT_GE(view.elevation_deg, 0.0);
    EXPECT_LE(view.elevation_deg, 90.0);
    if (view.elevation_deg > 75.0) ++near_pole;
  }
  // The cap above 75 deg holds (1 - sin 75)/1 = 3.4 % of the hemisphere's area.
  EXPECT_LT(near_pole, static_cast<int>(views.size() * 0.06));
}

TEST(ViewsTest, CameraLooksAtCentreFromTheRequestedDirection) {
  const Eigen::Vector3d centre(10, -5, 30);
  for (double elevation : {0.0, 30.0, 60.0, 89.0, 90.0}) {
    for (double roll : {-45.0, 0.0, 30.0}) {
      const Pose pose = CamFromModelForView({120.0, elevation, roll}, centre, 700.0);
      EXPECT_THAT(pose * centre, test::MatrixNear(Eigen::Vector3d(0, 0, 700), 1e-9));
      EXPECT_NEAR(pose.R.determinant(), 1.0, 1e-9);
      EXPECT_THAT((pose.R * pose.R.transpose()).eval(),
                  test::MatrixNear(Eigen::Matrix3d::Identity(), 1e-9));
      // Camera position in the model frame lies at the requested elevation.
      const Eigen::Vector3d camera_in_model = pose.Inverse().t - centre;
      EXPECT_NEAR(std::asin(camera_in_model.z() / 700.0) * 180.0 / kPi, elevation, 1e-6);
    }
  }
}

TEST(ViewsTest, ObjectUpAppearsUpInTheImageWithoutRoll) {
  const Pose pose = CamFromModelForView({0.0, 20.0, 0.0}, Eigen::Vector3d::Zero(), 700.0);
  const Eigen::Vector3d up_in_cam = pose.R * Eigen::Vector3d::UnitZ();
  EXPECT_LT(up_in_cam.y(), -0.9);  // image y grows downwards
  EXPECT_NEAR(up_in_cam.x(), 0.0, 1e-9);
}

TEST(DepthLayersTest, CoverRangeWithinHalfStep) {
  const double radius = 100.7;
  const auto layers = DepthLayers(600.0, 1200.0, radius);
  EXPECT_EQ(layers.size(), 6u);
  for (double depth = 600.0; depth <= 1200.0; depth += 1.0) {
    double nearest = 1e9;
    for (double layer : layers) nearest = std::min(nearest, std::abs(layer - depth));
    EXPECT_LE(nearest, radius / 2.0 + 1e-9) << depth;
  }
  for (double layer : layers) {
    EXPECT_GE(layer, 600.0);
    EXPECT_LE(layer, 1200.0);
  }
}

TEST(DepthLayersTest, RejectsBadRanges) {
  EXPECT_THROW(DepthLayers(900, 600, 50), Error);
  EXPECT_THROW(DepthLayers(600, 600, 50), Error);
  EXPECT_THROW(DepthLayers(600, 900, 0), Error);
  EXPECT_THROW(DepthLayers(-5, 900, 50), Error);
  EXPECT_THROW(DepthLayers(600, NAN, 50), Error);
}

}  // namespace
}  // namespace layermod
