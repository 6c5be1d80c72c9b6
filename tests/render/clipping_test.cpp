// SPDX-License-Identifier: MIT
#include "render/clipping.h"

#include <gtest/gtest.h>

#include "geometry/camera.h"
#include "support/test_cameras.h"

namespace layermod::render_internal {
namespace {

TEST(ClippingTest, TriangleInsideIsUnchanged) {
  const ScreenProjection projection(test::RoundedKinectCamera(), 1.0f);
  const Eigen::Vector3f a(0, 0, 500), b(50, 0, 600), c(0, 40, 700);
  const ClipPolygon polygon = ClipTriangle(a, b, c, kBehindNear | kOutsideLeft, projection);
  ASSERT_EQ(polygon.size, 3);
  EXPECT_EQ(polygon.vertices[0], a);
  EXPECT_EQ(polygon.vertices[1], b);
  EXPECT_EQ(polygon.vertices[2], c);
}

TEST(ClippingTest, NearPlaneCutsOffTheVertexBehind) {
  const ScreenProjection projection(test::RoundedKinectCamera(), 10.0f);
  const ClipPolygon polygon =
      ClipTriangle({0, 0, -100}, {50, 0, 600}, {0, 40, 700}, kBehindNear, projection);
  ASSERT_EQ(polygon.size, 4);
  int on_near_plane = 0;
  for (int i = 0; i < polygon.size; ++i) {
    EXPECT_GE(polygon.vertices[i].z(), 10.0f - 1e-4f);
    if (std::abs(polygon.vertices[i].z() - 10.0f) < 1e-4f) ++on_near_plane;
  }
  EXPECT_EQ(on_near_plane, 2);
}

TEST(ClippingTest, TriangleOutsideVanishes) {
  const ScreenProjection projection(test::RoundedKinectCamera(), 1.0f);
  EXPECT_EQ(ClipTriangle({0, 0, -1}, {5, 0, -2}, {0, 5, 0.5f}, kBehindNear, projection).size, 0);
  // Far to the left of the guard band.
  EXPECT_EQ(
      ClipTriangle({-9000, 0, 100}, {-9000, 50, 100}, {-8000, 0, 100}, kOutsideLeft, projection)
          .size,
      0);
}

TEST(ClippingTest, SharedEdgeIsCutAtIdenticalPoints) {
  // Two triangles sharing edge ab, listing it in opposite directions, as adjacent faces do.
  const ScreenProjection projection(test::RoundedKinectCamera(), 1.0f);
  const Eigen::Vector3f a(-13.7f, 2.9f, -57.3f), b(21.1f, -8.3f, 311.9f);
  const ClipPolygon first = ClipTriangle(a, b, {40, 30, 200}, kBehindNear, projection);
  const ClipPolygon second = ClipTriangle(b, a, {-40, 30, 250}, kBehindNear, projection);
  int shared = 0;
  for (int i = 0; i < first.size; ++i) {
    for (int j = 0; j < second.size; ++j) {
      if (first.vertices[i] == second.vertices[j] && first.vertices[i] != b) ++shared;
    }
  }
  EXPECT_EQ(shared, 1);  // the cut point of edge ab, bit for bit
}

}  // namespace
}  // namespace layermod::render_internal
