// SPDX-License-Identifier: MIT
#include "templates/template_picture.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace layermod {
namespace {

RenderMesh Square(float half_mm) {
  RenderMesh mesh;
  mesh.positions = {{-half_mm, -half_mm, 0},
                    {half_mm, -half_mm, 0},
                    {half_mm, half_mm, 0},
                    {-half_mm, half_mm, 0}};
  mesh.colors.assign(4, Eigen::Vector3f(0.2f, 0.4f, 0.9f));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// A template 500 mm in front of the camera, its box around the 40 mm square's projection, with
// one feature of each modality.
TemplateRecord FacingTemplate() {
  TemplateRecord record;
  record.cam_from_model.t = {0.0, 0.0, 500.0};
  record.bbox_px = cv::Rect(150, 110, 20, 20);
  TemplateLevel level;
  level.width = 20;
  level.height = 20;
  level.features = {{3, 4, 2, Modality::kColorGradient}, {10, 10, 5, Modality::kDepthNormal}};
  record.levels = {level};
  return record;
}

const PinholeCamera kCamera{250.0, 250.0, 160.0, 120.0, 320, 240};

int ColouredPixels(const cv::Mat& bgr) {
  std::vector<cv::Mat> channels;
  cv::split(bgr, channels);
  cv::Mat any = channels[0] | channels[1] | channels[2];
  return cv::countNonZero(any);
}

TEST(TemplatePictureTest, DrawsTheMeshAtTheTemplatePoseUnderItsFeatures) {
  const RenderMesh mesh = Square(20.0f);
  const cv::Mat picture = RenderTemplatePicture(FacingTemplate(), kCamera, &mesh);
  ASSERT_FALSE(picture.empty());
  EXPECT_EQ(picture.type(), CV_8UC3);
  // The square projects to 20 x 20 px, shaded (not black) inside the render's padded box.
  EXPECT_GE(picture.cols, 20);
  EXPECT_GE(picture.rows, 20);
  EXPECT_GT(ColouredPixels(picture), 19 * 19);
  EXPECT_LT(ColouredPixels(picture), 22 * 22);
}

TEST(TemplatePictureTest, WithoutAMeshDrawsTheFeaturesOnBlackAroundTheirBox) {
  const cv::Mat picture = RenderTemplatePicture(FacingTemplate(), kCamera, nullptr);
  ASSERT_FALSE(picture.empty());
  EXPECT_EQ(picture.size(), cv::Size(32, 32));  // the 20 px box and 6 px on each side
  const int drawn = ColouredPixels(picture);
  EXPECT_GT(drawn, 0);
  EXPECT_LT(drawn, 40);  // two features with their ticks, the rest black
}

TEST(TemplatePictureTest, AMeshOutOfViewFallsBackToTheFeatures) {
  const RenderMesh mesh = Square(20.0f);
  TemplateRecord record = FacingTemplate();
  record.cam_from_model.t = {0.0, 0.0, -500.0};  // behind the camera: nothing renders
  const cv::Mat picture = RenderTemplatePicture(record, kCamera, &mesh);
  EXPECT_EQ(picture.size(), cv::Size(32, 32));
}

TEST(TemplatePictureTest, NothingToDrawGivesAnEmptyPicture) {
  TemplateRecord record;
  EXPECT_TRUE(RenderTemplatePicture(record, kCamera, nullptr).empty());
}

TEST(TemplatePictureTest, FitInSquareKeepsTheAspectAndCentresOnBlack) {
  const cv::Mat wide(10, 40, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Mat square = FitInSquare(wide, 80);
  ASSERT_EQ(square.size(), cv::Size(80, 80));
  EXPECT_EQ(ColouredPixels(square), 80 * 20);  // scaled 2x: 80 x 20, rows 30..49
  EXPECT_EQ(square.at<cv::Vec3b>(39, 40), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(square.at<cv::Vec3b>(10, 40), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(ColouredPixels(FitInSquare(cv::Mat(), 16)), 0);
}

}  // namespace
}  // namespace layermod
