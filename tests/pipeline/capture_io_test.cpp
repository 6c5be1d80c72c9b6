// SPDX-License-Identifier: MIT
#include "pipeline/capture_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "support/test_paths.h"
#include "support/thrown.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

using test::ThrownMessage;
using ::testing::AllOf;
using ::testing::HasSubstr;

class CaptureIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    WriteFileAtomically(dir_ / "camera.json",
                        R"({"fx": 300, "fy": 300, "cx": 31.5, "cy": 23.5, "width": 64,
                            "height": 48, "depth_scale": 1.0})");
    cv::imwrite((dir_ / "color.png").string(), cv::Mat(48, 64, CV_8UC3, cv::Scalar(10, 20, 30)));
    cv::Mat depth(48, 64, CV_16U, cv::Scalar(800));
    depth(cv::Rect(0, 0, 8, 8)).setTo(0);
    cv::imwrite((dir_ / "depth.png").string(), depth);
    files_.color = dir_ / "color.png";
    files_.depth = dir_ / "depth.png";
    files_.camera = dir_ / "camera.json";
  }

  std::string LoadError() const {
    return ThrownMessage<Error>([this] { LoadCapture(files_); });
  }

  test::TempDir dir_;
  CaptureFiles files_;
};

TEST_F(CaptureIoTest, LoadsColourDepthAndCamera) {
  const Capture capture = LoadCapture(files_);
  EXPECT_EQ(capture.camera.width, 64);
  EXPECT_EQ(capture.color.type(), CV_8UC3);
  EXPECT_EQ(capture.color.at<cv::Vec3b>(5, 5), cv::Vec3b(10, 20, 30));
  ASSERT_EQ(capture.depth_mm.type(), CV_32F);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(20, 20), 800.0f);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(2, 2), 0.0f);
}

TEST_F(CaptureIoTest, DepthScaleGivesMillimetres) {
  files_.depth_scale = 0.1;  // 16-bit values in tenths of a millimetre
  EXPECT_FLOAT_EQ(LoadCapture(files_).depth_mm.at<float>(20, 20), 80.0f);
  files_.depth_scale = -1.0;
  EXPECT_THAT(LoadError(), HasSubstr("depth scale must be a positive number"));
}

TEST_F(CaptureIoTest, ColourWithoutDepthIsAnRgbCapture) {
  files_.depth.clear();
  EXPECT_TRUE(LoadCapture(files_).depth_mm.empty());
}

TEST_F(CaptureIoTest, GreyColourBecomesThreeChannels) {
  cv::imwrite((dir_ / "grey.png").string(), cv::Mat(48, 64, CV_8U, cv::Scalar(77)));
  files_.color = dir_ / "grey.png";
  const Capture capture = LoadCapture(files_);
  EXPECT_EQ(capture.color.type(), CV_8UC3);
  EXPECT_EQ(capture.color.at<cv::Vec3b>(1, 1), cv::Vec3b(77, 77, 77));
}

TEST_F(CaptureIoTest, FloatDepthInMetresAndItsInvalidValues) {
  cv::Mat depth(48, 64, CV_32F, cv::Scalar(0.75f));
  depth.at<float>(0, 0) = std::numeric_limits<float>::quiet_NaN();
  depth.at<float>(0, 1) = std::numeric_limits<float>::infinity();
  depth.at<float>(0, 2) = -0.5f;
  cv::imwrite((dir_ / "depth.tiff").string(), depth);
  files_.depth = dir_ / "depth.tiff";
  files_.float_depth_unit = DepthUnit::kMetre;
  const Capture capture = LoadCapture(files_);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(10, 10), 750.0f);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(0, 1), 0.0f);
  EXPECT_FLOAT_EQ(capture.depth_mm.at<float>(0, 2), 0.0f);
}

TEST_F(CaptureIoTest, NamesTheFileAndTheProblem) {
  files_.color = dir_ / "missing.png";
  EXPECT_THAT(LoadError(), AllOf(HasSubstr("missing.png"), HasSubstr("no such file")));
  SetUp();
  WriteFileAtomically(dir_ / "broken.png", "not an image");
  files_.color = dir_ / "broken.png";
  EXPECT_THAT(LoadError(), AllOf(HasSubstr("broken.png"), HasSubstr("not a readable image")));
  SetUp();
  cv::imwrite((dir_ / "wide.png").string(), cv::Mat(48, 80, CV_8UC3, cv::Scalar(1, 2, 3)));
  files_.color = dir_ / "wide.png";
  EXPECT_THAT(LoadError(), HasSubstr("image is 80x48 but"));
}

TEST_F(CaptureIoTest, RefusesDepthThatCannotBeMillimetres) {
  cv::imwrite((dir_ / "depth8.png").string(), cv::Mat(48, 64, CV_8U, cv::Scalar(200)));
  files_.depth = dir_ / "depth8.png";
  EXPECT_THAT(LoadError(), HasSubstr("8-bit depth image"));
  cv::imwrite((dir_ / "zeros.png").string(), cv::Mat(48, 64, CV_16U, cv::Scalar(0)));
  files_.depth = dir_ / "zeros.png";
  EXPECT_THAT(LoadError(), HasSubstr("no valid depth"));
  cv::imwrite((dir_ / "small.png").string(), cv::Mat(24, 32, CV_16U, cv::Scalar(500)));
  files_.depth = dir_ / "small.png";
  EXPECT_THAT(LoadError(), HasSubstr("small.png"));
}

}  // namespace
}  // namespace layermod
