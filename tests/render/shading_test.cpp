// SPDX-License-Identifier: MIT
#include "render/shading.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/camera.h"

namespace layermod::render_internal {
namespace {

const PinholeCamera kCamera{500, 500, 32, 32, 64, 64};

// A grey square on the plane z = 800 + 0.5 x (model = camera frame), turned 26.6 degrees about
// the y axis, facing the camera.
RenderMesh TiltedSquare() {
  RenderMesh mesh;
  for (const auto& [x, y] : {std::pair{-40.f, -40.f}, {40.f, -40.f}, {40.f, 40.f}, {-40.f, 40.f}}) {
    mesh.positions.emplace_back(x, y, 800.0f + 0.5f * x);
    mesh.colors.emplace_back(0.5f, 0.5f, 0.5f);
  }
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

RenderedView Shade(const RenderMesh& mesh, const PixelWindow& output) {
  const ScreenProjection projection(kCamera, 1.0f);
  const ViewVertices vertices = TransformVertices(mesh, Pose{}, projection);
  const VisibilityBuffer buffer =
      RasterizeVisibility(mesh, vertices, projection, PixelWindow{8, 8, 55, 55});
  return ShadeVisibility(mesh, vertices.in_cam, buffer, kCamera, RenderOptions{}, output);
}

// The plane's z where the ray through pixel (u, v) meets it.
double PlaneDepthAt(int u) { return 800.0 / (1.0 - 0.5 * (u - kCamera.cx) / kCamera.fx); }

TEST(ShadingTest, DepthIsWhereEachPixelRayMeetsTheTrianglePlane) {
  const RenderedView view = Shade(TiltedSquare(), PixelWindow{0, 0, 63, 63});
  ASSERT_EQ(view.roi, cv::Rect(0, 0, 64, 64));
  for (const int u : {20, 32, 44}) {
    EXPECT_NEAR(view.depth_mm.at<float>(32, u), PlaneDepthAt(u), 1e-2) << "u = " << u;
    EXPECT_EQ(view.mask.at<std::uint8_t>(32, u), 255);
  }
}

TEST(ShadingTest, NormalIsTheFaceNormalTurnedTowardsTheCamera) {
  const RenderedView view = Shade(TiltedSquare(), PixelWindow{0, 0, 63, 63});
  const cv::Vec3f normal = view.normals.at<cv::Vec3f>(30, 30);
  const double length = std::sqrt(1.25);
  EXPECT_NEAR(normal[0], 0.5 / length, 1e-5);
  EXPECT_NEAR(normal[1], 0.0, 1e-5);
  EXPECT_NEAR(normal[2], -1.0 / length, 1e-5);  // towards the camera at the origin
}

TEST(ShadingTest, ColourIsTheVertexColourTimesLambertShading) {
  const RenderedView view = Shade(TiltedSquare(), PixelWindow{0, 0, 63, 63});
  const RenderOptions options;
  const double lambert = options.ambient + (1.0 - options.ambient) * (1.0 / std::sqrt(1.25));
  const cv::Vec3b colour = view.color.at<cv::Vec3b>(32, 32);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(colour[c], 255.0 * 0.5 * lambert, 1.0);
}

TEST(ShadingTest, PixelsOutsideTheBufferOrTheSquareAreZero) {
  const RenderedView view = Shade(TiltedSquare(), PixelWindow{0, 0, 63, 63});
  for (const cv::Point outside : {cv::Point(2, 2), cv::Point(60, 32), cv::Point(32, 4)}) {
    EXPECT_EQ(view.mask.at<std::uint8_t>(outside), 0);
    EXPECT_EQ(view.depth_mm.at<float>(outside), 0.0f);
    EXPECT_EQ(view.color.at<cv::Vec3b>(outside), cv::Vec3b(0, 0, 0));
  }
}

TEST(ShadingTest, BlankViewIsZeroOverItsWindow) {
  const RenderedView view = BlankView(PixelWindow{4, 6, 13, 10});
  EXPECT_EQ(view.roi, cv::Rect(4, 6, 10, 5));
  EXPECT_EQ(view.depth_mm.size(), cv::Size(10, 5));
  EXPECT_EQ(cv::countNonZero(view.mask), 0);
  EXPECT_TRUE(view.empty());
}

}  // namespace
}  // namespace layermod::render_internal
