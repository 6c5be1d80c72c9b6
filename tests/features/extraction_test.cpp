// SPDX-License-Identifier: MIT
#include "features/extraction.h"
#include "features/template_edges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "features/synthetic_views.h"
#include "util/error.h"

namespace layermod {
namespace {

// A 150 x 150 view at odd camera offsets (exercises the pyramid alignment): a square pyramid of
// half-size 55 px whose four faces have distinct colours and normals.
constexpr int kHalfPx = 55;
const cv::Point kCentrePx(376, 246);

RenderedView TestView() {
  return test::PyramidView({301, 171, 150, 150}, kCentrePx, kHalfPx, 800.0f, 60.0f);
}

int CountModality(const TemplateLevel& level, Modality modality) {
  return static_cast<int>(std::count_if(level.features.begin(), level.features.end(),
                                        [&](const Feature& f) { return f.modality == modality; }));
}

// Camera pixel of a feature, at its own level.
cv::Point CameraPixel(const ExtractedTemplate& tmpl, int level, const Feature& f) {
  return {(tmpl.bbox_px.x >> level) + f.x, (tmpl.bbox_px.y >> level) + f.y};
}

TEST(ExtractTemplateTest, CountsAsRequestedAtEveryLevel) {
  FeatureOptions options;  // 63 + 63, two levels
  const ExtractedTemplate tmpl = ExtractTemplate(TestView(), test::KinectCamera(), options);
  ASSERT_EQ(tmpl.levels.size(), 2u);
  EXPECT_EQ(tmpl.levels[0].pyramid_level, 0);
  EXPECT_EQ(tmpl.levels[1].pyramid_level, 1);
  EXPECT_EQ(CountModality(tmpl.levels[0], Modality::kColorGradient), 63);
  EXPECT_EQ(CountModality(tmpl.levels[0], Modality::kDepthNormal), 63);
  EXPECT_EQ(CountModality(tmpl.levels[1], Modality::kColorGradient), 31);
  EXPECT_EQ(CountModality(tmpl.levels[1], Modality::kDepthNormal), 31);
  EXPECT_EQ(tmpl.FeatureCount(0), 126);
  EXPECT_EQ(tmpl.FeatureCount(5), 0);
}

TEST(ExtractTemplateTest, MoreThan63FeaturesPerModality) {
  FeatureOptions options;
  options.color_features = 150;
  options.normal_features = 150;
  options.pyramid_levels = 3;
  options.spread_px = {5, 8, 8};
  const ExtractedTemplate tmpl = ExtractTemplate(TestView(), test::KinectCamera(), options);
  EXPECT_EQ(CountModality(tmpl.levels[0], Modality::kColorGradient), 150);
  EXPECT_EQ(CountModality(tmpl.levels[0], Modality::kDepthNormal), 150);
  EXPECT_EQ(CountModality(tmpl.levels[2], Modality::kColorGradient), 37);
}

TEST(ExtractTemplateTest, ColourOnEdgesNormalsInsideWithTheirFaceLabels) {
  const RenderedView view = TestView();
  const ExtractedTemplate tmpl = ExtractTemplate(view, test::KinectCamera(), FeatureOptions{});
  cv::Mat near_mask, interior;
  cv::dilate(view.mask, near_mask, cv::Mat(), cv::Point(-1, -1), 1);
  cv::erode(view.mask, interior, cv::Mat(), cv::Point(-1, -1), 2);
  int silhouette_sides = 0, face_labels = 0, normals = 0;
  for (const Feature& f : tmpl.levels[0].features) {
    const cv::Point camera_px = CameraPixel(tmpl, 0, f);
    const cv::Point local = camera_px - view.roi.tl();
    const int du = camera_px.x - kCentrePx.x, dv = camera_px.y - kCentrePx.y;
    if (f.modality == Modality::kColorGradient) {
      ASSERT_NE(near_mask.at<std::uint8_t>(local), 0) << "colour feature off the object";
      // Straight silhouette sides (away from corners): vertical sides 0 deg, horizontal 90 deg.
      const bool on_side = std::abs(std::abs(du) - kHalfPx) <= 1 && std::abs(dv) < kHalfPx - 8;
      const bool on_top = std::abs(std::abs(dv) - kHalfPx) <= 1 && std::abs(du) < kHalfPx - 8;
      if (on_side) {
        EXPECT_EQ(f.label, 0);
      }
      if (on_top) {
        EXPECT_EQ(f.label, 4);
      }
      silhouette_sides += on_side || on_top;
    } else {
      ASSERT_NE(interior.at<std::uint8_t>(local), 0) << "normal feature too near the silhouette";
      // Faces lean away from the apex: right face's normal points right (0), bottom's down (2).
      // Normal features avoid label borders, such as the ridges between faces.
      const int expected = std::abs(du) >= std::abs(dv) ? (du >= 0 ? 0 : 4) : (dv >= 0 ? 2 : 6);
      ++normals;
      face_labels += f.label == expected;
      EXPECT_GT(std::abs(std::abs(du) - std::abs(dv)), 1) << "normal feature on a ridge";
    }
  }
  EXPECT_GT(silhouette_sides, 20);
  EXPECT_EQ(face_labels, normals);
}

TEST(ExtractTemplateTest, BoxContainsEveryLevelAndLevelOneIsHalfLevelZero) {
  const RenderedView view = TestView();
  const ExtractedTemplate tmpl = ExtractTemplate(view, test::KinectCamera(), FeatureOptions{});
  ASSERT_GT(tmpl.bbox_px.area(), 0);
  EXPECT_TRUE((view.roi & tmpl.bbox_px) == tmpl.bbox_px);
  EXPECT_EQ(tmpl.levels[0].width, tmpl.bbox_px.width);
  EXPECT_EQ(tmpl.levels[0].height, tmpl.bbox_px.height);
  EXPECT_NEAR(tmpl.levels[1].width, tmpl.bbox_px.width / 2.0, 1.0);
  EXPECT_NEAR(tmpl.levels[1].height, tmpl.bbox_px.height / 2.0, 1.0);
  cv::Rect level_box[2];
  for (int k = 0; k < 2; ++k) {
    const TemplateLevel& level = tmpl.levels[k];
    for (const Feature& f : level.features) {
      ASSERT_GE(f.x, 0);
      ASSERT_GE(f.y, 0);
      ASSERT_LT(f.x, level.width);
      ASSERT_LT(f.y, level.height);
      const cv::Rect at_level_zero(CameraPixel(tmpl, k, f) * (1 << k), cv::Size(1, 1));
      level_box[k] = level_box[k].area() == 0 ? at_level_zero : (level_box[k] | at_level_zero);
    }
  }
  // Both levels see the same object: their feature boxes agree to a couple of pixels.
  EXPECT_NEAR(level_box[1].x, level_box[0].x, 3);
  EXPECT_NEAR(level_box[1].y, level_box[0].y, 3);
  EXPECT_NEAR(level_box[1].br().x, level_box[0].br().x, 3);
  EXPECT_NEAR(level_box[1].br().y, level_box[0].br().y, 3);
  EXPECT_TRUE((tmpl.bbox_px | level_box[0] | level_box[1]) == tmpl.bbox_px);
}

TEST(ExtractTemplateTest, LevelOneFeaturesLieOnTheObjectScaledUp) {
  const RenderedView view = TestView();
  const ExtractedTemplate tmpl = ExtractTemplate(view, test::KinectCamera(), FeatureOptions{});
  cv::Mat near_mask;
  cv::dilate(view.mask, near_mask, cv::Mat(), cv::Point(-1, -1), 3);
  for (const Feature& f : tmpl.levels[1].features) {
    const cv::Point local = CameraPixel(tmpl, 1, f) * 2 - view.roi.tl();
    ASSERT_TRUE(cv::Rect({}, view.roi.size()).contains(local));
    EXPECT_NE(near_mask.at<std::uint8_t>(local), 0);
  }
}

TEST(ExtractTemplateTest, OnePixelShiftShiftsTheBoxOnly) {
  FeatureOptions colour_only;       // one level: level 1 samples other pixels after the shift
  colour_only.normal_features = 0;  // normals change slightly with the viewing ray; colour must not
  colour_only.pyramid_levels = 1;
  colour_only.spread_px = {5};
  const RenderedView shifted_view =
      test::PyramidView({302, 172, 150, 150}, kCentrePx + cv::Point(1, 1), kHalfPx, 800.0f, 60.0f);
  const ExtractedTemplate a = ExtractTemplate(TestView(), test::KinectCamera(), colour_only);
  const ExtractedTemplate b = ExtractTemplate(shifted_view, test::KinectCamera(), colour_only);
  EXPECT_EQ(b.bbox_px, a.bbox_px + cv::Point(1, 1));
  EXPECT_EQ(b.levels[0], a.levels[0]);
}

TEST(ExtractTemplateTest, DeterministicAndModalitiesCanBeSwitchedOff) {
  const RenderedView view = TestView();
  const PinholeCamera camera = test::KinectCamera();
  FeatureOptions options;
  const ExtractedTemplate first = ExtractTemplate(view, camera, options);
  const ExtractedTemplate second = ExtractTemplate(view, camera, options);
  EXPECT_EQ(first.bbox_px, second.bbox_px);
  EXPECT_EQ(first.levels, second.levels);

  options.color_features = 0;
  const ExtractedTemplate normals_only = ExtractTemplate(view, camera, options);
  EXPECT_EQ(CountModality(normals_only.levels[0], Modality::kColorGradient), 0);
  EXPECT_EQ(CountModality(normals_only.levels[1], Modality::kColorGradient), 0);
  EXPECT_EQ(CountModality(normals_only.levels[0], Modality::kDepthNormal), 63);
}

TEST(ExtractTemplateTest, EmptyViewGivesEmptyLevels) {
  const PinholeCamera camera = test::KinectCamera();
  RenderedView view = TestView();
  view.mask.setTo(0);
  for (const RenderedView& empty : {view, RenderedView{}}) {
    const ExtractedTemplate tmpl = ExtractTemplate(empty, camera, FeatureOptions{});
    ASSERT_EQ(tmpl.levels.size(), 2u);
    EXPECT_TRUE(tmpl.levels[0].features.empty());
    EXPECT_TRUE(tmpl.levels[1].features.empty());
    EXPECT_EQ(tmpl.levels[1].pyramid_level, 1);
    EXPECT_EQ(tmpl.bbox_px.area(), 0);
  }
}

TEST(ExtractTemplateTest, BadOptionsAndBadViewsThrow) {
  const PinholeCamera camera = test::KinectCamera();
  FeatureOptions options;
  options.pyramid_levels = 3;  // spread_px still has two values
  EXPECT_THROW(ExtractTemplate(TestView(), camera, options), Error);
  RenderedView view = TestView();
  view.depth_mm = cv::Mat(view.depth_mm.size(), CV_16U, cv::Scalar(0));
  EXPECT_THROW(ExtractTemplate(view, camera, FeatureOptions{}), Error);
}

// ---- depth-edge counts of templates ----

TEST(TemplateDepthEdgeCountTest, DiscSilhouetteCountsAboutTwiceItsPerimeter) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Point2d centre(300.0, 200.0);
  const double layer_mm = 800.0;
  const double diameter_mm = 100.0 * layer_mm / camera.fx;  // a 100 px window
  for (double radius_px : {15.0, 30.0, 45.0}) {
    const RenderedView view =
        test::DiscView({240, 140, 121, 121}, centre, radius_px, static_cast<float>(layer_mm));
    const int count = TemplateDepthEdgeCount(view, camera, centre, diameter_mm, layer_mm, 40.0f);
    // Both sides of the silhouette step respond: two pixels per pixel of perimeter on straight
    // axis-aligned stretches, a little more where the 3x3 window straddles a slanted edge.
    const double perimeter = 2.0 * CV_PI * radius_px;
    EXPECT_GT(count, 2.0 * perimeter) << "radius " << radius_px;
    EXPECT_LT(count, 3.0 * perimeter) << "radius " << radius_px;
  }
}

TEST(TemplateDepthEdgeCountTest, WindowOutsideTheRoiIsBackground) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Point2d centre(300.0, 200.0);
  const RenderedView tight = test::DiscView({270, 170, 61, 61}, centre, 25.0, 700.0f);
  const RenderedView wide = test::DiscView({200, 100, 201, 201}, centre, 25.0, 700.0f);
  const double diameter_mm = 90.0 * 700.0 / camera.fx;
  const int tight_count = TemplateDepthEdgeCount(tight, camera, centre, diameter_mm, 700.0, 30.0f);
  EXPECT_EQ(tight_count, TemplateDepthEdgeCount(wide, camera, centre, diameter_mm, 700.0, 30.0f));
  EXPECT_GT(tight_count, 0);
  // Far from the object: nothing.
  EXPECT_EQ(TemplateDepthEdgeCount(tight, camera, {50.0, 50.0}, diameter_mm, 700.0, 30.0f), 0);
}

// A camera looking straight down at the model's XY plane from `height_mm` above it.
SupportPlane PlaneFacingCamera(double height_mm) {
  SupportPlane plane;
  plane.cam_from_model.R = Eigen::Vector3d(1.0, -1.0, -1.0).asDiagonal();  // model +Z to camera
  plane.cam_from_model.t = Eigen::Vector3d(0.0, 0.0, height_mm);
  return plane;
}

TEST(SupportPlaneDepthTest, FrontoParallelPlaneHasConstantDepth) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Mat depth =
      SupportPlaneDepth(camera, PlaneFacingCamera(900.0), {10, 20, 30, 40}, 5000.0f);
  ASSERT_EQ(depth.size(), cv::Size(30, 40));
  double low = 0.0;
  double high = 0.0;
  cv::minMaxLoc(depth, &low, &high);
  EXPECT_NEAR(low, 900.0, 1e-3);
  EXPECT_NEAR(high, 900.0, 1e-3);
}

TEST(SupportPlaneDepthTest, TiltedPlaneFollowsTheRayIntersection) {
  const PinholeCamera camera = test::KinectCamera();
  // Tilt the plane 75 degrees about the camera x axis; a plane point stays at (0, 0, 1000).
  SupportPlane plane = PlaneFacingCamera(1000.0);
  plane.cam_from_model.R =
      Eigen::AngleAxisd(DegToRad(75.0), Eigen::Vector3d::UnitX()).toRotationMatrix() *
      plane.cam_from_model.R;
  const cv::Rect window(0, 0, camera.width, camera.height);
  const cv::Mat depth = SupportPlaneDepth(camera, plane, window, 1e6f);
  const Eigen::Vector3d normal = plane.cam_from_model.R.col(2);
  for (const cv::Point pixel : {cv::Point(320, 100), cv::Point(50, 300), cv::Point(600, 240)}) {
    const double z = depth.at<float>(pixel);
    const Eigen::Vector3d point = camera.Backproject(Eigen::Vector2d(pixel.x, pixel.y), z);
    EXPECT_NEAR(normal.dot(point - Eigen::Vector3d(0.0, 0.0, 1000.0)), 0.0, 0.05 * z / 1000.0)
        << pixel;
  }
  // The bottom rows look above the tilted plane's horizon: they see the far value.
  const cv::Mat edge_on = SupportPlaneDepth(camera, plane, {0, camera.height - 1, 640, 1}, 3000.0f);
  double low = 0.0;
  cv::minMaxLoc(edge_on, &low);
  EXPECT_EQ(low, 3000.0);
}

TEST(TemplateDepthEdgeCountTest, SupportPlaneJustBehindHidesTheSilhouette) {
  const PinholeCamera camera = test::KinectCamera();
  const cv::Point2d centre(camera.cx, camera.cy);
  const RenderedView disc = test::DiscView({270, 190, 101, 101}, centre, 30.0, 700.0f);
  const double diameter_mm = 100.0 * 700.0 / camera.fx;
  const SupportPlane close_behind = PlaneFacingCamera(720.0);  // a 20 mm step
  const SupportPlane far_behind = PlaneFacingCamera(900.0);    // a 200 mm step
  const int against_far = TemplateDepthEdgeCount(disc, camera, centre, diameter_mm, 700.0, 30.0f);
  EXPECT_GT(against_far, 0);
  EXPECT_EQ(TemplateDepthEdgeCount(disc, camera, centre, diameter_mm, 700.0, 30.0f, &close_behind),
            0);
  EXPECT_EQ(TemplateDepthEdgeCount(disc, camera, centre, diameter_mm, 700.0, 30.0f, &far_behind),
            against_far);
}

TEST(TemplateDepthEdgeCountTest, RejectsNonsense) {
  const PinholeCamera camera = test::KinectCamera();
  const RenderedView view = test::DiscView({270, 170, 61, 61}, {300.0, 200.0}, 25.0, 700.0f);
  EXPECT_THROW(TemplateDepthEdgeCount(view, camera, {300.0, 200.0}, 0.0, 700.0, 30.0f), Error);
  EXPECT_THROW(TemplateDepthEdgeCount(view, camera, {300.0, 200.0}, 100.0, -1.0, 30.0f), Error);
  EXPECT_THROW(TemplateDepthEdgeCount(view, camera, {300.0, 200.0}, 100.0, 700.0, 0.0f), Error);
  EXPECT_EQ(TemplateDepthEdgeCount(RenderedView{}, camera, {300.0, 200.0}, 100.0, 700.0, 30.0f), 0);
}

}  // namespace
}  // namespace layermod
