// SPDX-License-Identifier: MIT
#include "geometry/camera.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/matchers.h"
#include "support/test_cameras.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(CameraTest, ProjectBackprojectRoundTrip) {
  const PinholeCamera camera = test::KinectCamera();
  const Eigen::Vector3d point(12.0, -40.0, 800.0);
  const Eigen::Vector2d pixel = camera.Project(point);
  EXPECT_THAT(camera.Backproject(pixel, 800.0), test::MatrixNear(point, 1e-9));
}

TEST(CameraTest, ScaledKeepsContinuousCoordinates) {
  const PinholeCamera half = test::KinectCamera().Scaled(0.5);
  EXPECT_EQ(half.width, 320);
  EXPECT_EQ(half.height, 240);
  const Eigen::Vector3d point(50.0, 20.0, 700.0);
  // (u + 0.5) halves exactly.
  const Eigen::Vector2d full = test::KinectCamera().Project(point);
  const Eigen::Vector2d scaled = half.Project(point);
  EXPECT_NEAR(scaled.x() + 0.5, (full.x() + 0.5) * 0.5, 1e-9);
  EXPECT_NEAR(scaled.y() + 0.5, (full.y() + 0.5) * 0.5, 1e-9);
}

TEST(CameraTest, EveryNthPixelMapsPixelCentresExactly) {
  const PinholeCamera full = test::KinectCamera();
  const PinholeCamera sampled = full.EveryNthPixel(3);
  EXPECT_EQ(sampled.width, 214);  // 640 / 3 rounded up: pixel 639 = 3 * 213 is the last one
  EXPECT_EQ(sampled.height, 160);
  for (const Eigen::Vector3d& point :
       {Eigen::Vector3d(50.0, 20.0, 700.0), Eigen::Vector3d(-230.0, 140.0, 1250.0)}) {
    const Eigen::Vector2d in_full = full.Project(point);
    const Eigen::Vector2d in_sampled = sampled.Project(point);
    EXPECT_NEAR(in_full.x(), 3.0 * in_sampled.x(), 1e-9);
    EXPECT_NEAR(in_full.y(), 3.0 * in_sampled.y(), 1e-9);
  }
  EXPECT_EQ(full.EveryNthPixel(1), full);
  EXPECT_THROW(full.EveryNthPixel(0), Error);
}

TEST(CameraTest, LoadsBopCameraFile) {
  test::TempDir dir;
  WriteFileAtomically(dir / "camera.json",
                      R"({"cx": 325.2611, "cy": 242.04899, "depth_scale": 1.0, "fx": 572.4114,
                          "fy": 573.57043, "height": 480, "width": 640})");
  EXPECT_EQ(LoadCameraJson(dir / "camera.json"), test::KinectCamera());
}

TEST(CameraTest, WrittenJsonReadsBackAsTheSameCamera) {
  test::TempDir dir;
  WriteFileAtomically(dir / "camera.json", CameraJson(test::KinectCamera()).dump());
  EXPECT_EQ(LoadCameraJson(dir / "camera.json"), test::KinectCamera());
  EXPECT_EQ(CameraJson(test::KinectCamera()).size(), 6u);  // exactly the six fields, nothing else
}

TEST(CameraTest, MissingFieldIsNamed) {
  test::TempDir dir;
  WriteFileAtomically(dir / "camera.json", R"({"cx": 1, "cy": 2, "fx": 3, "fy": 4, "width": 640})");
  try {
    LoadCameraJson(dir / "camera.json");
    FAIL() << "expected FormatError";
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find("'height' is missing"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("camera.json"), std::string::npos);
  }
}

TEST(CameraTest, RejectsBadValues) {
  test::TempDir dir;
  WriteFileAtomically(dir / "neg.json",
                      R"({"cx": 1, "cy": 2, "fx": -3, "fy": 4, "width": 640, "height": 480})");
  WriteFileAtomically(dir / "str.json",
                      R"({"cx": "1", "cy": 2, "fx": 3, "fy": 4, "width": 640, "height": 480})");
  WriteFileAtomically(dir / "frac.json",
                      R"({"cx": 1, "cy": 2, "fx": 3, "fy": 4, "width": 640.5, "height": 480})");
  WriteFileAtomically(dir / "junk.json", "not json");
  EXPECT_THROW(LoadCameraJson(dir / "neg.json"), FormatError);
  EXPECT_THROW(LoadCameraJson(dir / "str.json"), FormatError);
  EXPECT_THROW(LoadCameraJson(dir / "frac.json"), FormatError);
  EXPECT_THROW(LoadCameraJson(dir / "junk.json"), FormatError);
  EXPECT_THROW(LoadCameraJson(dir / "absent.json"), IoError);
}

}  // namespace
}  // namespace layermod
