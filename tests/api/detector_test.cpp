// SPDX-License-Identifier: MIT
#include <layermod/detector.h>
#include <layermod/error.h>

#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <thread>

#include "api_fixture.h"

namespace layermod::api {
namespace {

using test::kSampleDetectorOptions;
using test::Sample;

// Throws what `detector.Detect(capture)` throws and returns its message ("" if nothing).
std::string DetectError(const Detector& detector, const Capture& capture) {
  try {
    detector.Detect(capture);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(ApiDetectorTest, FindsThePartNearItsTruePose) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  for (const test::SampleFrame& frame : Sample().frames) {
    const DetectionResult result = detector.Detect(frame.capture);
    ASSERT_FALSE(result.detections.empty());
    const Detection& best = result.detections.front();
    EXPECT_EQ(best.obj_id, 1);
    EXPECT_EQ(best.name, "bracket");
    EXPECT_LT((best.t_mm - frame.true_t_mm).norm(), 15.0);
    EXPECT_TRUE((best.R * best.R.transpose()).isIdentity(1e-9));
    EXPECT_GT(result.timings.total_ms, 0.0);
    EXPECT_EQ(result.mode, "scene-patch");
  }
}

// Detect is const and only reads the detector: two threads on one detector give exactly the
// results one thread gives.
TEST(ApiDetectorTest, OneDetectorServesTwoThreads) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  std::vector<Eigen::Vector3d> alone;
  for (const test::SampleFrame& frame : Sample().frames) {
    alone.push_back(detector.Detect(frame.capture).detections.at(0).t_mm);
  }
  std::vector<std::vector<Eigen::Vector3d>> seen(2);
  auto run = [&](std::size_t thread) {
    for (int round = 0; round < 3; ++round) {
      for (const test::SampleFrame& frame : Sample().frames) {
        const DetectionResult result = detector.Detect(frame.capture);
        seen[thread].push_back(result.detections.empty() ? Eigen::Vector3d::Zero()
                                                         : result.detections[0].t_mm);
      }
    }
  };
  std::thread first(run, 0);
  std::thread second(run, 1);
  first.join();
  second.join();
  for (const auto& poses : seen) {
    ASSERT_EQ(poses.size(), 3 * alone.size());
    for (std::size_t i = 0; i < poses.size(); ++i) EXPECT_EQ(poses[i], alone[i % alone.size()]);
  }
}

TEST(ApiDetectorTest, SixteenBitDepthEqualsFloatDepth) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  Capture as_float = Sample().frames[1].capture;
  Capture as_u16 = as_float;
  as_float.depth.convertTo(as_u16.depth, CV_16U, 10.0);  // 0.1 mm steps
  as_u16.depth_scale = 0.1;
  const DetectionResult a = detector.Detect(as_float);
  const DetectionResult b = detector.Detect(as_u16);
  ASSERT_EQ(a.detections.size(), b.detections.size());
  ASSERT_FALSE(a.detections.empty());
  EXPECT_LT((a.detections[0].t_mm - b.detections[0].t_mm).norm(), 1e-6);
}

TEST(ApiDetectorTest, NanAndNegativeDepthCountAsNoMeasurement) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  Capture capture = Sample().frames[0].capture;
  capture.depth = capture.depth.clone();
  capture.depth(cv::Rect(0, 0, 40, 40)).setTo(std::numeric_limits<float>::quiet_NaN());
  capture.depth(cv::Rect(600, 0, 40, 40)).setTo(-5.0f);
  capture.depth(cv::Rect(0, 440, 40, 40)).setTo(std::numeric_limits<float>::infinity());
  const DetectionResult result = detector.Detect(capture);
  ASSERT_FALSE(result.detections.empty());
  EXPECT_LT((result.detections[0].t_mm - Sample().frames[0].true_t_mm).norm(), 15.0);
}

// Confidence is left out (0): the counts below are about the LineMOD threshold alone.
TEST(ApiDetectorTest, OptionsUseTheCliNames) {
  const Detector detector({Sample().archive},
                          R"({"threshold": 99.5, "instances": 2, "min_confidence": 0})");
  const auto options = nlohmann::json::parse(detector.OptionsJson());
  EXPECT_EQ(options["threshold"], 99.5);
  EXPECT_EQ(options["instances"], 2);
  const Detector loose = detector.WithOptions(R"({"threshold": 70, "min_confidence": 0})");
  EXPECT_EQ(loose.archives().size(), 1u);
  EXPECT_LT(detector.Detect(Sample().frames[0].capture).detections.size(),
            loose.Detect(Sample().frames[0].capture).detections.size());
  EXPECT_THROW(Detector({Sample().archive}, R"({"no_such_option": 1})"), FormatError);
  EXPECT_THROW(Detector({Sample().archive}, R"({"threshold": 500})"), FormatError);
  EXPECT_THROW(Detector({Sample().archive}, "threshold=70"), FormatError);
  EXPECT_THROW(Detector({}), Error);
  EXPECT_THROW(Detector({Sample().archive, Sample().archive}), Error);  // id 1 twice
}

TEST(ApiDetectorTest, UnusableCapturesThrowNamingTheProblem) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  const Capture good = Sample().frames[0].capture;
  Capture capture = good;
  capture.color_bgr.convertTo(capture.color_bgr, CV_32FC3);
  EXPECT_NE(DetectError(detector, capture).find("CV_8UC3"), std::string::npos);
  capture = good;
  good.depth.convertTo(capture.depth, CV_64F);
  EXPECT_NE(DetectError(detector, capture).find("CV_16UC1"), std::string::npos);
  capture = good;
  capture.depth = good.depth(cv::Rect(0, 0, 320, 240)).clone();
  EXPECT_NE(DetectError(detector, capture).find("differ in size"), std::string::npos);
  capture = good;
  capture.camera.fx = 600.0;
  EXPECT_NE(DetectError(detector, capture).find("intrinsics differ"), std::string::npos);
  capture = good;
  capture.depth = cv::Mat();
  EXPECT_NE(DetectError(detector, capture).find("needs depth"), std::string::npos);
  capture = good;
  capture.depth.convertTo(capture.depth, CV_16U);
  capture.depth_scale = 0.0;
  EXPECT_NE(DetectError(detector, capture).find("depth_scale"), std::string::npos);
}

TEST(ApiDetectorTest, JsonIsTheCliFormat) {
  const Detector detector({Sample().archive}, kSampleDetectorOptions);
  const DetectionResult result = detector.Detect(Sample().frames[0].capture);
  ASSERT_FALSE(result.detections.empty());
  const auto json = nlohmann::json::parse(ToJson(result));
  EXPECT_EQ(json["mode"], "scene-patch");
  const auto& first = json["detections"][0];
  EXPECT_EQ(first["obj_id"], 1);
  EXPECT_EQ(first["template_id"], result.detections[0].template_id);
  EXPECT_DOUBLE_EQ(first["cam_R_m2c"][1].get<double>(), result.detections[0].R(0, 1));
  EXPECT_DOUBLE_EQ(first["cam_t_m2c"][2].get<double>(), result.detections[0].t_mm.z());
  EXPECT_DOUBLE_EQ(json["timings_ms"]["total"].get<double>(), result.timings.total_ms);
}

}  // namespace
}  // namespace layermod::api
