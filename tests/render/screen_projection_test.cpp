// SPDX-License-Identifier: MIT
#include "render/screen_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/triangle_raster.h"
#include "support/test_cameras.h"

namespace layermod::render_internal {
namespace {

TEST(ScreenProjectionTest, PixelCentresMapToExactFixedPointCentres) {
  const PinholeCamera camera = test::RoundedKinectCamera();
  const ScreenProjection projection(camera, 1.0f);
  for (const int u : {0, 17, 325, 639}) {
    for (const int v : {0, 100, 479}) {
      const Eigen::Vector3d point = camera.Backproject({u, v}, 834.5);
      const ScreenVertex vertex = projection.Project(point.cast<float>());
      EXPECT_EQ(vertex.x, PixelCentreFixed(u));
      EXPECT_EQ(vertex.y, PixelCentreFixed(v));
      EXPECT_NEAR(vertex.inv_z, 1.0 / 834.5, 1e-9);
    }
  }
}

std::uint32_t OutcodeOf(const ScreenProjection& projection, const Eigen::Vector3d& point) {
  ScreenVertex screen;
  projection.ProjectVertex(point.cast<float>(), screen);
  return screen.outcode;
}

TEST(ScreenProjectionTest, OutcodesNameTheViolatedPlanes) {
  const PinholeCamera camera = test::RoundedKinectCamera();
  const ScreenProjection projection(camera, 5.0f);
  EXPECT_EQ(OutcodeOf(projection, {0, 0, 500}), 0u);
  EXPECT_EQ(OutcodeOf(projection, {0, 0, 5}), kBehindNear);  // on the near plane counts as behind
  EXPECT_EQ(OutcodeOf(projection, {3000, 0, -500}), kBehindNear);
  EXPECT_EQ(OutcodeOf(projection, {0, 0, std::nan("")}), kInvalid);
  EXPECT_EQ(OutcodeOf(projection, {std::numeric_limits<double>::infinity(), 0, 100}), kInvalid);
  // Beyond the guard band on each side, at 100 mm.
  const double beyond_px = kGuardBandPx + 10.0;
  const auto at = [&](double u, double v) { return camera.Backproject({u, v}, 100.0); };
  EXPECT_EQ(OutcodeOf(projection, at(-beyond_px, 200)), kOutsideLeft);
  EXPECT_EQ(OutcodeOf(projection, at(639 + beyond_px, 200)), kOutsideRight);
  EXPECT_EQ(OutcodeOf(projection, at(300, -beyond_px)), kOutsideTop);
  EXPECT_EQ(OutcodeOf(projection, at(-beyond_px, 479 + beyond_px)), kOutsideLeft | kOutsideBottom);
  EXPECT_EQ(OutcodeOf(projection, at(-kGuardBandPx + 10.0, 479 + kGuardBandPx - 10.0)), 0u);
}

TEST(ScreenProjectionTest, GuardPlanesMatchTheGuardBand) {
  // A point on the left guard plane projects onto the guard band's edge.
  const PinholeCamera camera = test::RoundedKinectCamera();
  const ScreenProjection projection(camera, 1.0f);
  const Eigen::Vector3f on_left = camera.Backproject({-kGuardBandPx, 100}, 300.0).cast<float>();
  // The plane value is fx * z * (u + guard): 1 here is far below a thousandth of a pixel.
  EXPECT_NEAR(projection.PlaneValue(1, on_left), 0.0f, 1.0f);
  EXPECT_GT(projection.PlaneValue(1, on_left + Eigen::Vector3f(1, 0, 0)), 0.0f);
  EXPECT_LT(
      projection.PlaneValue(2, camera.Backproject({700 + kGuardBandPx, 0}, 50.0).cast<float>()),
      0.0f);
}

}  // namespace
}  // namespace layermod::render_internal
