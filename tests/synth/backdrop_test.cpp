// SPDX-License-Identifier: MIT
#include "synth/backdrop.h"

#include <gtest/gtest.h>

#include "support/matchers.h"
#include "synth/scene_layout.h"
#include "synth_fixtures.h"

namespace layermod {
namespace {

// A camera `height_mm` above the world origin looking straight down (image x = world x).
Pose LookingDown(double height_mm) {
  Pose cam_from_world;
  cam_from_world.R << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  cam_from_world.t = Eigen::Vector3d(0.0, 0.0, height_mm);
  return cam_from_world;
}

Backdrop MakeTestBackdrop(const Eigen::AlignedBox2d& table, const Eigen::Vector3d& camera) {
  std::mt19937_64 rng(2);
  return MakeBackdrop(table, Eigen::Vector2d::Zero(), camera, {}, rng);
}

TEST(BackdropTest, TableSeenFromAboveHasConstantDepthAndWorldCoordinates) {
  const PinholeCamera camera = test::SmallCamera();
  const Eigen::AlignedBox2d table(Eigen::Vector2d(-2000, -2000), Eigen::Vector2d(2000, 2000));
  const Backdrop backdrop = MakeTestBackdrop(table, {0.0, 0.0, 800.0});
  ASSERT_EQ(backdrop.planes.size(), 3u);
  const BackdropPixels pixels = IntersectBackdrop(backdrop, camera, LookingDown(800.0));
  for (const cv::Point pixel : {cv::Point(0, 0), cv::Point(162, 120), cv::Point(319, 239)}) {
    EXPECT_EQ(pixels.plane_index.at<schar>(pixel), kTablePlane);
    EXPECT_NEAR(pixels.depth_mm.at<float>(pixel), 800.0f, 1e-3f);
    const cv::Vec2f xy = pixels.plane_xy.at<cv::Vec2f>(pixel);
    EXPECT_NEAR(xy[0], 800.0 * (pixel.x - camera.cx) / camera.fx, 1e-3);
    EXPECT_NEAR(xy[1], -800.0 * (pixel.y - camera.cy) / camera.fy, 1e-3);
  }
}

TEST(BackdropTest, BeyondTheTableIsTheFloor) {
  const PinholeCamera camera = test::SmallCamera();
  const Eigen::AlignedBox2d table(Eigen::Vector2d(-100, -100), Eigen::Vector2d(100, 100));
  const Backdrop backdrop = MakeTestBackdrop(table, {0.0, 0.0, 800.0});
  const BackdropPixels pixels = IntersectBackdrop(backdrop, camera, LookingDown(800.0));
  const double floor_depth = 800.0 - backdrop.planes[1].world_from_plane.t.z();
  EXPECT_GT(floor_depth, 1400.0);
  EXPECT_EQ(pixels.plane_index.at<schar>(0, 0), 1);
  EXPECT_NEAR(pixels.depth_mm.at<float>(0, 0), floor_depth, 1e-3);
  EXPECT_EQ(pixels.plane_index.at<schar>(120, 162), kTablePlane);
}

TEST(BackdropTest, LowCamerasSeeTheWallBehindTheTarget) {
  const PinholeCamera camera = test::SmallCamera();
  const Eigen::AlignedBox2d table(Eigen::Vector2d(-500, -500), Eigen::Vector2d(1200, 500));
  const Eigen::Vector3d centre(900.0, 0.0, 100.0);  // nearly level, looking along -x
  const Backdrop backdrop = MakeTestBackdrop(table, centre);
  const Pose cam_from_world =
      LookAtFrom(Eigen::Vector3d(0.0, 0.0, 60.0), centre, 0.0, camera, {camera.cx, camera.cy});
  const BackdropPixels pixels = IntersectBackdrop(backdrop, camera, cam_from_world);
  EXPECT_EQ(pixels.plane_index.at<schar>(0, 162), 2);     // the top row: the wall
  EXPECT_GT(pixels.depth_mm.at<float>(0, 162), 1500.0f);  // 1..2.5 m behind the target
  EXPECT_EQ(pixels.plane_index.at<schar>(239, 162), kTablePlane);
}

TEST(BackdropTest, ShadingScalesTheTextureByLambert) {
  const PinholeCamera camera = test::SmallCamera();
  const Eigen::AlignedBox2d table(Eigen::Vector2d(-2000, -2000), Eigen::Vector2d(2000, 2000));
  Backdrop backdrop = MakeTestBackdrop(table, {0.0, 0.0, 800.0});
  backdrop.planes[kTablePlane].texture.setTo(cv::Scalar(200, 100, 50));
  const BackdropPixels pixels = IntersectBackdrop(backdrop, camera, LookingDown(800.0));
  const Eigen::Vector3d light = Eigen::Vector3d(0.0, 0.6, 0.8);
  const cv::Mat color = ShadeBackdrop(backdrop, pixels, light, 0.5);
  const double shade = 0.5 + 0.5 * 0.8;
  EXPECT_EQ(color.at<cv::Vec3b>(100, 100),
            cv::Vec3b(cv::saturate_cast<uchar>(200 * shade), cv::saturate_cast<uchar>(100 * shade),
                      cv::saturate_cast<uchar>(50 * shade)));
}

}  // namespace
}  // namespace layermod
