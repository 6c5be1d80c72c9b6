// SPDX-License-Identifier: MIT
#include "dataset/image_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <string>
#include <vector>

#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {
using test::ThrownMessage;
using ::testing::HasSubstr;

std::string Encode(const std::string& extension, const cv::Mat& image) {
  std::vector<unsigned char> bytes;
  cv::imencode(extension, image, bytes);
  return {bytes.begin(), bytes.end()};
}

TEST(ImageHeaderTest, ReadsTheSizeOfPngAndJpegWithoutDecoding) {
  const cv::Mat image(48, 64, CV_8UC3, cv::Scalar(10, 20, 30));
  EXPECT_EQ(DeclaredImageSize(Encode(".png", image)), cv::Size(64, 48));
  EXPECT_EQ(DeclaredImageSize(Encode(".jpg", image)), cv::Size(64, 48));
  EXPECT_EQ(DeclaredImageSize(Encode(".png", cv::Mat(5, 7, CV_16U, cv::Scalar(900)))),
            cv::Size(7, 5));
  EXPECT_EQ(DeclaredImageSize("not an image"), std::nullopt);
  EXPECT_EQ(DeclaredImageSize(Encode(".png", image).substr(0, 20)), std::nullopt);
}

TEST(ImageHeaderTest, HugeDeclaredSizesAreRefusedBeforeDecoding) {
  std::string png = Encode(".png", cv::Mat(48, 64, CV_16U, cv::Scalar(900)));
  for (int i = 16; i < 24; ++i) png[static_cast<std::size_t>(i)] = i % 4 == 0 ? '\x00' : '\x7f';
  EXPECT_THAT(ThrownMessage<FormatError>(
                  [&] { CheckDeclaredImageSize("depth.png", png, std::nullopt, ""); }),
              HasSubstr("'depth.png': image declares"));
}

TEST(ImageHeaderTest, ASizeOtherThanTheCamerasIsNamed) {
  const std::string jpg = Encode(".jpg", cv::Mat(48, 64, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_NO_THROW(CheckDeclaredImageSize("c.jpg", jpg, cv::Size(64, 48), "'camera.json'"));
  EXPECT_THAT(ThrownMessage<FormatError>([&] {
                CheckDeclaredImageSize("c.jpg", jpg, cv::Size(640, 480), "'camera.json'");
              }),
              HasSubstr("'c.jpg': image is 64x48 but 'camera.json' says 640x480"));
}

}  // namespace
}  // namespace layermod
