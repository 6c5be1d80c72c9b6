// SPDX-License-Identifier: MIT
#include "pose/initial_pose.h"

#include <gtest/gtest.h>

#include "geometry/views.h"
#include "pose/pose_test_scene.h"
#include "support/matchers.h"

namespace layermod {
namespace {

// A template as training makes it: the sphere centre on the optical axis at the layer depth.
TemplateRecord OnAxisTemplate(double layer_mm) {
  TemplateRecord tmpl;
  tmpl.layer_depth_mm = static_cast<float>(layer_mm);
  tmpl.cam_from_model =
      CamFromModelForView({30.0, 40.0, 0.0}, test::SampleModel().sphere.centre, layer_mm);
  tmpl.bbox_px = cv::Rect(270, 190, 100, 100);
  const PinholeCamera camera = test::VgaCamera();
  tmpl.centre_offset_px =
      cv::Point2f(static_cast<float>(camera.cx - 270), static_cast<float>(camera.cy - 190));
  tmpl.centre_minus_surface_mm = 20.0f;
  TemplateLevel level;
  for (int i = 0; i < 10; ++i) {
    level.features.push_back({static_cast<std::int16_t>(40 + i), 50, 1, Modality::kDepthNormal});
  }
  tmpl.levels.push_back(level);
  return tmpl;
}

TEST(InitialPoseTest, MatchAtTheTrainingPositionGivesTheTemplatePose) {
  const TemplateRecord tmpl = OnAxisTemplate(800.0);
  const Pose pose = PoseFromMatch(tmpl, tmpl.bbox_px.tl(), 800.0, test::SampleModel().sphere.centre,
                                  test::VgaCamera());
  EXPECT_THAT(pose, test::PoseNear(tmpl.cam_from_model, 1e-9, 1e-6));
}

TEST(InitialPoseTest, OffAxisMatchPutsTheCentreOnItsPixelAtTheDepth) {
  const TemplateRecord tmpl = OnAxisTemplate(800.0);
  const cv::Point box_tl(50, 300);
  const Eigen::Vector3d centre = test::SampleModel().sphere.centre;
  const Pose pose = PoseFromMatch(tmpl, box_tl, 950.0, centre, test::VgaCamera());
  const Eigen::Vector3d centre_in_cam = pose * centre;
  EXPECT_NEAR(centre_in_cam.z(), 950.0, 1e-6);
  const Eigen::Vector2d pixel = test::VgaCamera().Project(centre_in_cam);
  EXPECT_NEAR(pixel.x(), box_tl.x + tmpl.centre_offset_px.x, 1e-6);
  EXPECT_NEAR(pixel.y(), box_tl.y + tmpl.centre_offset_px.y, 1e-6);
  // The object is seen from the same direction relative to the viewing ray.
  const Eigen::Vector3d ray = centre_in_cam.normalized();
  const Eigen::Vector3d ray_in_model = pose.R.transpose() * ray;
  const Eigen::Vector3d axis_in_template_model =
      tmpl.cam_from_model.R.transpose() * Eigen::Vector3d::UnitZ();
  EXPECT_THAT(ray_in_model, test::MatrixNear(axis_in_template_model, 1e-9));
}

TEST(InitialPoseTest, CentreDepthFromNormalFeatures) {
  const TemplateRecord tmpl = OnAxisTemplate(800.0);
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(780.0f));
  EXPECT_NEAR(EstimateCentreDepthMm(tmpl, {100, 100}, depth), 800.0, 1e-4);
  depth.setTo(0.0f);
  EXPECT_EQ(EstimateCentreDepthMm(tmpl, {100, 100}, depth), 0.0);    // no valid depth
  EXPECT_EQ(EstimateCentreDepthMm(tmpl, {-500, -500}, depth), 0.0);  // outside the image
}

}  // namespace
}  // namespace layermod
