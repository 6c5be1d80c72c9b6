// SPDX-License-Identifier: MIT
// The detector's contract at its edges: captures and options it refuses, with the reason, and
// archives that cannot be combined.
#include "pipeline/detector.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>

#include "bracket_frame.h"
#include "eval_fixtures.h"
#include "pipeline/detection_poses.h"
#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {

using test::BracketFrame;
using test::ThrownMessage;
using ::testing::HasSubstr;

std::string DetectError(Capture capture, const DetectorOptions& options = {}) {
  return ThrownMessage<Error>([&] { BracketFrame().detector.Detect(capture, options); });
}

TEST(DetectorTest, FindsTheBracketInItsFrame) {
  const DetectionResult& result = BracketFrame().result;
  ASSERT_FALSE(result.detections.empty());
  EXPECT_EQ(result.detections.front().obj_id, 1);
  const Pose& found = result.detections.front().cam_from_model;
  EXPECT_LT((found.t - BracketFrame().truth.t).norm(), 5.0);
  const Eigen::AngleAxisd turn(found.R.transpose() * BracketFrame().truth.R);
  EXPECT_LT(RadToDeg(turn.angle()), 3.0);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_FALSE(result.diagnostics.front().division.blocks.empty());
  for (std::size_t i = 1; i < result.detections.size(); ++i) {
    EXPECT_FALSE(RanksHigher(result.detections[i], result.detections[i - 1]));
  }
}

TEST(DetectorTest, RefusesCapturesItCannotRead) {
  const Capture good = BracketFrame().capture;
  EXPECT_THAT(DetectError({cv::Mat(), good.depth_mm, good.camera}), HasSubstr("no colour image"));
  cv::Mat grey;
  cv::extractChannel(good.color, grey, 0);
  EXPECT_THAT(DetectError({grey, good.depth_mm, good.camera}), HasSubstr("8-bit, 3 channels"));
  const cv::Mat small = good.color(cv::Rect(0, 0, 100, 80)).clone();
  EXPECT_THAT(DetectError({small, good.depth_mm, good.camera}),
              HasSubstr("colour image is 100x80 but the camera is"));
  cv::Mat depth_16;
  good.depth_mm.convertTo(depth_16, CV_16U);
  EXPECT_THAT(DetectError({good.color, depth_16, good.camera}), HasSubstr("CV_32F"));
  const cv::Mat short_depth = good.depth_mm(cv::Rect(0, 0, 100, 80)).clone();
  EXPECT_THAT(DetectError({good.color, short_depth, good.camera}), HasSubstr("differ in size"));
}

TEST(DetectorTest, DepthIsNeededExceptInColourOnlyMode) {
  const Capture good = BracketFrame().capture;
  EXPECT_THAT(DetectError({good.color, cv::Mat(), good.camera}), HasSubstr("needs depth"));
  DetectorOptions colour_only;
  colour_only.mode = DetectionMode::kColorOnly;
  EXPECT_EQ(DetectError({good.color, cv::Mat(), good.camera}, colour_only), "");
}

TEST(DetectorTest, RefusesACameraOtherThanTheArchives) {
  Capture other = BracketFrame().capture;
  other.camera.fx *= 1.1;
  EXPECT_THAT(DetectError(other), HasSubstr("intrinsics differ"));
}

TEST(DetectorTest, NonFiniteDepthIsInvalidNotACrash) {
  Capture capture = BracketFrame().capture;
  capture.depth_mm = capture.depth_mm.clone();
  capture.depth_mm(cv::Rect(0, 0, 40, 30)).setTo(std::numeric_limits<float>::quiet_NaN());
  capture.depth_mm(cv::Rect(40, 0, 40, 30)).setTo(std::numeric_limits<float>::infinity());
  capture.depth_mm(cv::Rect(80, 0, 40, 30)).setTo(-500.0f);
  DetectorOptions options;
  options.min_confidence = 0.0;
  const DetectionResult result = BracketFrame().detector.Detect(capture, options);
  ASSERT_FALSE(result.detections.empty());
  EXPECT_TRUE(result.detections.front().cam_from_model.t.allFinite());
}

TEST(DetectorTest, RefusesInvalidOptions) {
  DetectorOptions options;
  options.min_confidence = 1.5;
  EXPECT_THAT(DetectError(BracketFrame().capture, options), HasSubstr("min_confidence"));
  options = {};
  options.max_instances = 0;
  EXPECT_THAT(DetectError(BracketFrame().capture, options), HasSubstr("max_instances"));
}

TEST(DetectorTest, RefusesArchivesThatCannotBeCombined) {
  EXPECT_THAT(ThrownMessage<Error>([] { Detector(std::vector<TemplateArchive>{}); }),
              HasSubstr("no archive"));
  const TemplateArchive bracket = test::TrainBracketArchive(600.0, 700.0);
  EXPECT_THAT(ThrownMessage<Error>([&] {
                Detector({bracket, bracket});
              }),
              HasSubstr("object id 1 appears twice"));
  EXPECT_THAT(ThrownMessage<Error>([] { BracketFrame().detector.Object(9); }),
              HasSubstr("no object 9"));
}

// An archive of format 2 or older (normals in the camera frame) cannot share a scene with a
// format 3 one: the scene's normals are quantized once, in one frame.
TEST(DetectorTest, RefusesArchivesWhoseNormalsAreInDifferentFrames) {
  const TemplateArchive bracket = test::TrainBracketArchive(600.0, 700.0);
  ArchiveManifest manifest = bracket.manifest();
  manifest.objects.at(0).obj_id = 2;
  manifest.objects.at(0).profile.features.normal_frame = NormalFrame::kCamera;
  std::vector<TemplateRecord> templates(bracket.templates().begin(), bracket.templates().end());
  for (TemplateRecord& record : templates) record.obj_id = 2;
  const TemplateArchive older(manifest, templates);
  EXPECT_THAT(ThrownMessage<Error>([&] {
                Detector({bracket, older});
              }),
              HasSubstr("archives quantize depth normals in different frames"));
  EXPECT_NO_THROW(Detector({older}));
}

}  // namespace
}  // namespace layermod
