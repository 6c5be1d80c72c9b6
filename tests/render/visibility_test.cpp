// SPDX-License-Identifier: MIT
#include "render/visibility.h"

#include <gtest/gtest.h>

#include "geometry/camera.h"

namespace layermod::render_internal {
namespace {

// Two overlapping squares facing the camera at the given depths (model = camera frame).
RenderMesh TwoSquares(float first_z, float second_z) {
  RenderMesh mesh;
  for (const float z : {first_z, second_z}) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(),
                          {{-50, -50, z}, {50, -50, z}, {50, 50, z}, {-50, 50, z}});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  }
  return mesh;
}

VisibilityBuffer Rasterize(const RenderMesh& mesh) {
  const PinholeCamera camera{500, 500, 32, 32, 64, 64};
  const ScreenProjection projection(camera, 1.0f);
  const ViewVertices vertices = TransformVertices(mesh, Pose{}, projection);
  return RasterizeVisibility(mesh, vertices, projection, PixelWindow{0, 0, 63, 63});
}

TEST(VisibilityTest, NearestTriangleWinsRegardlessOfOrder) {
  for (const bool near_first : {true, false}) {
    const VisibilityBuffer buffer =
        Rasterize(near_first ? TwoSquares(800, 900) : TwoSquares(900, 800));
    const int centre = 32 * 64 + 32;
    EXPECT_EQ(buffer.triangle[centre] / 2, near_first ? 0 : 1);
    EXPECT_FLOAT_EQ(buffer.inv_z[centre], 1.0f / 800.0f);
  }
}

TEST(VisibilityTest, EqualDepthKeepsTheFirstTriangle) {
  const VisibilityBuffer buffer = Rasterize(TwoSquares(800, 800));
  for (const std::int32_t id : buffer.triangle) EXPECT_LT(id, 2);  // never the second square
}

TEST(VisibilityTest, CoveredBoxHoldsThePixelCentresOfTheProjection) {
  const PinholeCamera camera{500, 500, 32, 32, 64, 64};
  const ScreenProjection projection(camera, 1.0f);
  // The near square spans u, v in [32 - 25, 32 + 25] = [7, 57]; the far one lies inside it.
  const ViewVertices near_and_far = TransformVertices(TwoSquares(1000, 2000), Pose{}, projection);
  EXPECT_EQ(near_and_far.covered_box.x0, 7);
  EXPECT_EQ(near_and_far.covered_box.y0, 7);
  EXPECT_EQ(near_and_far.covered_box.x1, 57);
  EXPECT_EQ(near_and_far.covered_box.y1, 57);
  EXPECT_FALSE(near_and_far.any_behind_near);
  // Shifted by 0.3 px: the first and last centres inside are 8 and 57.
  Pose shifted;
  shifted.t.x() = 0.3 * 1000.0 / 500.0;
  const ViewVertices moved = TransformVertices(TwoSquares(1000, 2000), shifted, projection);
  EXPECT_EQ(moved.covered_box.x0, 8);
  EXPECT_EQ(moved.covered_box.x1, 57);
  // Entirely behind the camera: nothing is covered.
  EXPECT_TRUE(TransformVertices(TwoSquares(-1000, -2000), Pose{}, projection).covered_box.empty());
}

}  // namespace
}  // namespace layermod::render_internal
