// SPDX-License-Identifier: MIT
#include "features/depth_normals.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>

#include "features/synthetic_views.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kDegToRad = CV_PI / 180.0;

double AngleDeg(const cv::Vec3f& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d av(a[0], a[1], a[2]);
  return std::acos(std::clamp(av.normalized().dot(b.normalized()), -1.0, 1.0)) / kDegToRad;
}

TEST(ComputeDepthNormalsTest, TiltedPlaneSeenOffCentreMatchesItsNormal) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Rect roi(430, 330, 120, 100);  // far from the principal point
  const Eigen::Vector3d normal = Eigen::Vector3d(0.5, -0.3, -1.0).normalized();
  const cv::Mat depth = test::PlaneDepth(camera, roi, {200.0, 150.0, 900.0}, normal);
  const cv::Mat normals = ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera);
  ASSERT_EQ(normals.type(), CV_32FC3);
  double worst_deg = 0.0;
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      worst_deg = std::max(worst_deg, AngleDeg(normals.at<cv::Vec3f>(v, u), normal));
    }
  }
  EXPECT_LT(worst_deg, 2.0);

  // The intrinsics matter: the same depth read as if it were at the image corner is wrong.
  const cv::Mat misplaced = ComputeDepthNormals(depth, camera, {0, 0}, 50.0f, NormalFrame::kCamera);
  EXPECT_GT(AngleDeg(misplaced.at<cv::Vec3f>(50, 60), normal), 5.0);
}

// A surface turned about the camera centre so that it is seen near the image corner instead of at
// the centre: in the viewing-ray frame its normal is the one it has at the centre; in the camera
// frame it is turned by the angle between the corner's ray and the optical axis.
TEST(ComputeDepthNormalsTest, ViewingRayFrameGivesTheNormalsSeenAtTheCentre) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Point corner(600, 450);
  const cv::Rect roi(corner.x - 20, corner.y - 20, 41, 41);
  const Eigen::Vector3d ray = camera.Backproject(Eigen::Vector2d(corner.x, corner.y), 1.0);
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), ray).toRotationMatrix();
  const Eigen::Vector3d at_centre = Eigen::AngleAxisd(35.0 * kDegToRad, Eigen::Vector3d::UnitX()) *
                                    Eigen::Vector3d(0.0, 0.0, -1.0);
  const cv::Mat depth =
      test::PlaneDepth(camera, roi, turn * Eigen::Vector3d(0.0, 0.0, 900.0), turn * at_centre);
  const cv::Mat in_rays =
      ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kViewingRay);
  const cv::Mat in_camera =
      ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera);
  const cv::Vec3f ray_frame = in_rays.at<cv::Vec3f>(20, 20);
  EXPECT_LT(AngleDeg(ray_frame, at_centre), 1.0);
  EXPECT_NEAR(cv::norm(ray_frame), 1.0, 1e-4);
  EXPECT_LT(AngleDeg(in_camera.at<cv::Vec3f>(20, 20), turn * at_centre), 1.0);
  const double off_axis_deg = std::acos(ray.normalized().z()) / kDegToRad;
  ASSERT_GT(off_axis_deg, 25.0);
  EXPECT_GT(AngleDeg(in_camera.at<cv::Vec3f>(20, 20), at_centre), 15.0);
  // Pixels away from the corner's ray are turned by their own rays, not by the corner's.
  const Eigen::Vector3d ray_below =
      camera.Backproject(Eigen::Vector2d(corner.x, corner.y + 15), 1.0);
  const Eigen::Matrix3d turn_below =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), ray_below).toRotationMatrix();
  EXPECT_LT(AngleDeg(in_rays.at<cv::Vec3f>(35, 20), turn_below.transpose() * turn * at_centre),
            1.0);
}

TEST(InViewingRayFrameTest, TakesTheRayToTheOpticalAxisAndKeepsLengths) {
  const cv::Vec3f along_ray = InViewingRayFrame(cv::Vec3f(0.3f, -0.2f, 1.0f), 0.3f, -0.2f);
  EXPECT_NEAR(along_ray[0], 0.0, 1e-6);
  EXPECT_NEAR(along_ray[1], 0.0, 1e-6);
  EXPECT_NEAR(along_ray[2], cv::norm(cv::Vec3f(0.3f, -0.2f, 1.0f)), 1e-5);
  const cv::Vec3f turned = InViewingRayFrame(cv::Vec3f(0.6f, 0.0f, -0.8f), -0.4f, 0.5f);
  EXPECT_NEAR(cv::norm(turned), 1.0, 1e-5);
  EXPECT_EQ(InViewingRayFrame(cv::Vec3f(0.0f, 0.0f, 0.0f), 0.7f, 0.2f),
            cv::Vec3f(0.0f, 0.0f, 0.0f));
  const cv::Vec3f centre = InViewingRayFrame(cv::Vec3f(0.6f, 0.0f, -0.8f), 0.0f, 0.0f);
  EXPECT_EQ(centre, cv::Vec3f(0.6f, 0.0f, -0.8f));
}

TEST(ComputeDepthNormalsTest, HolesOnlyRemoveTheirOwnPixels) {
  // Windows touching a hole take the general fit, the others the complete-window shortcut: both
  // must give the plane's normal.
  const PinholeCamera camera = test::KinectCamera();
  const cv::Rect roi(60, 300, 90, 70);
  const Eigen::Vector3d normal = Eigen::Vector3d(-0.4, 0.2, -1.0).normalized();
  cv::Mat depth = test::PlaneDepth(camera, roi, {-200.0, 60.0, 750.0}, normal);
  cv::RNG rng(7);
  for (int i = 0; i < 300; ++i) {
    depth.at<float>(rng.uniform(0, roi.height), rng.uniform(0, roi.width)) =
        i % 3 == 0 ? 0.0f : (i % 3 == 1 ? std::nanf("") : 5000.0f);  // hole, NaN, far outlier
  }
  const cv::Mat normals = ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera);
  int valid = 0;
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const float z = depth.at<float>(v, u);
      const cv::Vec3f& n = normals.at<cv::Vec3f>(v, u);
      if (!(z > 0.0f) || z > 4000.0f) {
        EXPECT_EQ(n, cv::Vec3f(0, 0, 0)) << u << ", " << v;  // no normal at invalid pixels
        continue;
      }
      ++valid;
      EXPECT_LT(AngleDeg(n, normal), 2.0) << u << ", " << v;
    }
  }
  EXPECT_GT(valid, roi.area() * 8 / 10);
}

TEST(ComputeDepthNormalsTest, SphereNormalsFollowTheSurface) {
  const PinholeCamera camera = test::KinectCamera();
  const Eigen::Vector3d centre(40.0, -30.0, 700.0);
  const double radius_mm = 80.0;
  const cv::Rect roi(300, 150, 120, 120);
  cv::Mat depth = cv::Mat::zeros(roi.size(), CV_32F);
  for (int v = 0; v < roi.height; ++v) {
    for (int u = 0; u < roi.width; ++u) {
      const Eigen::Vector3d ray =
          camera.Backproject(Eigen::Vector2d(u + roi.x, v + roi.y), 1.0).normalized();
      const double b = ray.dot(centre);
      const double disc = b * b - (centre.squaredNorm() - radius_mm * radius_mm);
      if (disc > 0.0) depth.at<float>(v, u) = static_cast<float>((b - std::sqrt(disc)) * ray.z());
    }
  }
  const cv::Mat normals = ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera);
  int checked = 0;
  for (int v = 0; v < roi.height; v += 3) {
    for (int u = 0; u < roi.width; u += 3) {
      const float z = depth.at<float>(v, u);
      if (z <= 0.0f) continue;
      const Eigen::Vector3d point = camera.Backproject(Eigen::Vector2d(u + roi.x, v + roi.y), z);
      const Eigen::Vector3d expected = (point - centre).normalized();
      if (-expected.dot(point.normalized()) < 0.5) continue;  // grazing rim: steep, few samples
      EXPECT_LT(AngleDeg(normals.at<cv::Vec3f>(v, u), expected), 3.0) << u << ", " << v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(ComputeDepthNormalsTest, NormalsAreUnitAndFaceTheCamera) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Rect roi(20, 30, 60, 50);
  const Eigen::Vector3d normal = Eigen::AngleAxisd(55.0 * kDegToRad, Eigen::Vector3d::UnitY()) *
                                 Eigen::Vector3d(0.0, 0.0, -1.0);
  const cv::Mat depth = test::PlaneDepth(camera, roi, {-250.0, -170.0, 800.0}, normal);
  const cv::Mat normals = ComputeDepthNormals(depth, camera, roi.tl(), 50.0f, NormalFrame::kCamera);
  for (int v = 0; v < roi.height; v += 7) {
    for (int u = 0; u < roi.width; u += 7) {
      const cv::Vec3f& n = normals.at<cv::Vec3f>(v, u);
      EXPECT_NEAR(cv::norm(n), 1.0, 1e-4);
      const Eigen::Vector3d ray = camera.Backproject(Eigen::Vector2d(u + roi.x, v + roi.y), 1.0);
      EXPECT_LT(n[0] * ray.x() + n[1] * ray.y() + n[2] * ray.z(), 0.0);
      EXPECT_LT(AngleDeg(n, normal), 2.0);
    }
  }
}

TEST(ComputeDepthNormalsTest, DepthStepsDoNotMixSurfaces) {
  cv::Mat depth(40, 40, CV_32F, cv::Scalar(800.0f));
  depth.colRange(20, 40).setTo(1000.0f);  // two frontal planes, 200 mm apart
  const cv::Mat normals =
      ComputeDepthNormals(depth, test::KinectCamera(), {300, 220}, 50.0f, NormalFrame::kCamera);
  for (int u = 15; u < 25; ++u) {
    EXPECT_LT(AngleDeg(normals.at<cv::Vec3f>(20, u), {0.0, 0.0, -1.0}), 1.0) << "column " << u;
  }
}

TEST(ComputeDepthNormalsTest, InvalidAndDiscontinuousDepthGivesZero) {
  const PinholeCamera camera = test::KinectCamera();
  cv::Mat depth = cv::Mat::zeros(30, 30, CV_32F);
  depth.at<float>(5, 5) = 900.0f;               // isolated pixel
  depth.row(15).colRange(2, 28).setTo(900.0f);  // a one-pixel line: no plane
  depth.at<float>(25, 25) = std::nanf("");      // NaN
  depth.at<float>(25, 26) = std::numeric_limits<float>::infinity();
  for (int x = 10; x < 20; ++x) {  // each pixel its own depth: no surface
    for (int y = 20; y < 30; ++y) depth.at<float>(y, x) = 500.0f + 100.0f * (x + 10 * (y - 20));
  }
  const cv::Mat normals = ComputeDepthNormals(depth, camera, {0, 0}, 50.0f, NormalFrame::kCamera);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 30; ++x) {
      EXPECT_EQ(normals.at<cv::Vec3f>(y, x), cv::Vec3f(0, 0, 0)) << x << ", " << y;
    }
  }
}

TEST(ComputeDepthNormalsTest, RejectsBadInput) {
  const PinholeCamera camera = test::KinectCamera();
  EXPECT_THROW(
      ComputeDepthNormals(cv::Mat(4, 4, CV_16U), camera, {0, 0}, 50.0f, NormalFrame::kCamera),
      Error);
  EXPECT_THROW(
      ComputeDepthNormals(cv::Mat(4, 4, CV_32F), camera, {0, 0}, 0.0f, NormalFrame::kCamera),
      Error);
  EXPECT_EQ(ComputeDepthNormals(cv::Mat(0, 0, CV_32F), camera, {0, 0}, 50.0f, NormalFrame::kCamera)
                .size(),
            cv::Size(0, 0));
}

}  // namespace
}  // namespace layermod
