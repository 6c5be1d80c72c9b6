// SPDX-License-Identifier: MIT
#include "synth/scene_render.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "synth/primitives.h"
#include "synth_fixtures.h"

namespace layermod {
namespace {

Sphere SphereOf(const RenderMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& p : mesh.positions) points.push_back(p.cast<double>());
  return MinimalEnclosingSphere(points);
}

// A grey box target at the origin, a camera 800 mm away at 30 degrees elevation along +x, and
// optionally a tall box between them.
class SceneRenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    target_mesh_ = MakeBoxMesh({80.0f, 80.0f, 80.0f}, {0.6f, 0.6f, 0.6f});
    occluder_mesh_ = MakeBoxMesh({40.0f, 200.0f, 250.0f}, {0.2f, 0.4f, 0.8f});
    layout_.items.push_back(PlaceUpright(target_mesh_, SphereOf(target_mesh_), 1, 0.0,
                                         Eigen::Vector3d::UnitX(), 0.0, {0.0, 0.0}));
    const Eigen::Vector3d target = layout_.items[0].bound.centre;
    layout_.camera.centre_in_world =
        target + 800.0 * Eigen::Vector3d(std::cos(DegToRad(30.0)), 0.0, std::sin(DegToRad(30.0)));
    layout_.camera.cam_from_world =
        LookAtFrom(target, layout_.camera.centre_in_world, 0.0, camera_, {camera_.cx, camera_.cy});
    layout_.table_extent =
        Eigen::AlignedBox2d(Eigen::Vector2d(-800, -800), Eigen::Vector2d(800, 800));
    std::mt19937_64 rng(1);
    backdrop_ =
        MakeBackdrop(layout_.table_extent, {0.0, 0.0}, layout_.camera.centre_in_world, {}, rng);
    for (BackdropPlane& plane : backdrop_.planes) plane.texture.setTo(cv::Scalar::all(200));
  }

  void AddOccluder(double y_mm) {
    layout_.items.push_back(PlaceUpright(occluder_mesh_, SphereOf(occluder_mesh_), 0, 0.0,
                                         Eigen::Vector3d::UnitX(), 0.0, {150.0, y_mm}));
  }

  PinholeCamera camera_ = test::SmallCamera();
  RenderMesh target_mesh_;
  RenderMesh occluder_mesh_;
  SceneLayout layout_;
  Backdrop backdrop_;
};

TEST_F(SceneRenderTest, AloneTheTargetIsFullyVisible) {
  SceneRender render;
  RenderScene(layout_, backdrop_, camera_, render);
  ASSERT_EQ(render.item_views.size(), 1u);
  EXPECT_DOUBLE_EQ(VisibleFraction(render, 0), 1.0);
  EXPECT_EQ(render.item_index.at<short>(120, 162), 0);
  EXPECT_EQ(render.item_index.at<short>(239, 0), kTableSurface);
  // Composite depth: the target where it is seen, the table elsewhere.
  EXPECT_EQ(render.depth_mm.at<float>(120, 162), render.item_views[0].depth_mm.at<float>(120, 162));
  EXPECT_EQ(render.depth_mm.at<float>(239, 0), render.backdrop.depth_mm.at<float>(239, 0));
}

TEST_F(SceneRenderTest, AnOccluderHidesPartOfTheTarget) {
  AddOccluder(110.0);  // covers one side of the target
  SceneRender render;
  RenderScene(layout_, backdrop_, camera_, render);
  const double visible = VisibleFraction(render, 0);
  EXPECT_GT(visible, 0.05);
  EXPECT_LT(visible, 0.95);
  const cv::Mat no_depth = cv::Mat::zeros(render.depth_mm.size(), CV_32F);
  const WholeSilhouette whole = ItemWholeSilhouette(layout_, camera_, 0);
  const BopGtInfo info = ItemGtInfo(render, 0, whole, render.depth_mm);
  // Inside the image, the whole silhouette is the one rendered in the image.
  EXPECT_EQ(info.px_count_all, cv::countNonZero(render.item_views[0].mask));
  EXPECT_EQ(info.px_count_valid, info.px_count_all);
  EXPECT_EQ(info.px_count_visib, cv::countNonZero(render.item_index == 0));
  EXPECT_DOUBLE_EQ(info.visib_fract, visible);
  EXPECT_EQ(info.bbox_obj, cv::boundingRect(render.item_views[0].mask));
  EXPECT_LT(info.bbox_visib.area(), info.bbox_obj.area());
  EXPECT_EQ(ItemGtInfo(render, 0, whole, no_depth).px_count_valid, 0);

  // Removing the occluder and recompositing restores the target.
  render.item_views.pop_back();
  Composite(render);
  EXPECT_DOUBLE_EQ(VisibleFraction(render, 0), 1.0);
}

TEST_F(SceneRenderTest, ItemsOutsideTheImageHaveNoBox) {
  AddOccluder(5000.0);
  SceneRender render;
  RenderScene(layout_, backdrop_, camera_, render);
  const BopGtInfo info =
      ItemGtInfo(render, 1, ItemWholeSilhouette(layout_, camera_, 1), render.depth_mm);
  EXPECT_EQ(info.px_count_visib, 0);
  EXPECT_EQ(info.bbox_obj, cv::Rect(-1, -1, -1, -1));
  EXPECT_EQ(info.bbox_visib, cv::Rect(-1, -1, -1, -1));
  EXPECT_EQ(info.visib_fract, 0.0);
}

// BOP counts a part cut by the image border against its whole silhouette: half of it in the
// image is half visible, even with nothing in front of it.
TEST_F(SceneRenderTest, APartCutByTheImageBorderIsPartlyVisible) {
  const Eigen::Vector3d target = layout_.items[0].bound.centre;
  layout_.camera.cam_from_world =
      LookAtFrom(target, layout_.camera.centre_in_world, 0.0, camera_, {0.0, camera_.cy});
  SceneRender render;
  RenderScene(layout_, backdrop_, camera_, render);
  const int in_image = cv::countNonZero(render.item_views[0].mask);
  ASSERT_GT(in_image, 0);
  EXPECT_DOUBLE_EQ(VisibleFraction(render, 0), 1.0);  // of what the image shows

  const BopGtInfo info =
      ItemGtInfo(render, 0, ItemWholeSilhouette(layout_, camera_, 0), render.depth_mm);
  EXPECT_EQ(info.px_count_visib, in_image);
  EXPECT_GT(info.px_count_all, in_image);
  EXPECT_GT(info.visib_fract, 0.3);
  EXPECT_LT(info.visib_fract, 0.7);
  EXPECT_LT(info.bbox_obj.x, 0);  // the whole box reaches out of the image
  EXPECT_EQ(info.bbox_visib.x, 0);
  EXPECT_EQ(info.bbox_obj & info.bbox_visib, info.bbox_visib);
}

TEST_F(SceneRenderTest, ItemsCastShadowsOnTheTable) {
  layout_.light_to_world = Eigen::Vector3d::UnitZ();
  layout_.ambient = 0.4;
  SceneRender render;
  RenderScene(layout_, backdrop_, camera_, render);
  const cv::Mat item_color = render.color.clone();
  PaintBackdrop(layout_, backdrop_, render);
  // Item pixels keep their colour; table pixels are painted.
  EXPECT_EQ(render.color.at<cv::Vec3b>(120, 162), item_color.at<cv::Vec3b>(120, 162));
  // The table right below the box (just in front of its base) is darker than far from it.
  const Eigen::Vector3d near_base = layout_.camera.cam_from_world * Eigen::Vector3d(48.0, 0.0, 0.0);
  const Eigen::Vector2d pixel = camera_.Project(near_base);
  const cv::Point near(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
  ASSERT_EQ(render.item_index.at<short>(near), kTableSurface);
  EXPECT_LT(render.color.at<cv::Vec3b>(near)[1] + 10, render.color.at<cv::Vec3b>(235, 5)[1]);
}

}  // namespace
}  // namespace layermod
