// SPDX-License-Identifier: MIT
#include "dataset/bop_writer.h"
#include "support/thrown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "support/test_cameras.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using test::ThrownMessage;

// A frame with random colour, integer depth in mm, and two instances with awkward numbers.
BopFrame RandomFrame(int image_id, std::mt19937_64& rng) {
  BopFrame frame;
  frame.scene_id = 1;
  frame.image_id = image_id;
  frame.camera = test::ManyDigitsCamera();
  frame.color.create(60, 80, CV_8UC3);
  cv::randu(frame.color, 0, 256);
  frame.depth_mm.create(60, 80, CV_32F);
  std::uniform_int_distribution<int> depth(0, 3000);
  frame.depth_mm.forEach<float>([&](float& value, const int*) { value = 0.0f; });
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 80; ++x) frame.depth_mm.at<float>(y, x) = static_cast<float>(depth(rng));
  }
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int obj_id : {3, 12}) {
    BopGroundTruth gt;
    gt.obj_id = obj_id;
    gt.cam_from_model.R =
        Eigen::AngleAxisd(unit(rng) * 3.0, Eigen::Vector3d(unit(rng), unit(rng), 1.0).normalized())
            .toRotationMatrix();
    gt.cam_from_model.t = {unit(rng) * 100.0, unit(rng) * 100.0, 700.0 + unit(rng) * 1e-7};
    frame.gt.push_back(gt);
    BopGtInfo info;
    info.bbox_obj = {1, 2, 30, 40};
    info.bbox_visib = {-1, -1, -1, -1};
    info.px_count_all = 1000 + obj_id;
    info.px_count_valid = 900;
    info.px_count_visib = 0;
    info.visib_fract = 1.0 / 3.0;
    frame.gt_info.push_back(info);
  }
  return frame;
}

TEST(BopWriterTest, RoundTripIsExact) {
  test::TempDir dir;
  std::mt19937_64 rng(7);
  std::vector<BopFrame> frames;
  for (int id : {0, 1, 10}) frames.push_back(RandomFrame(id, rng));
  BopSceneWriter writer(dir / "test" / "000001");
  // Out of order and from several threads, as the generator adds them.
  std::vector<std::thread> threads;
  for (int i : {2, 0, 1}) threads.emplace_back([&, i] { writer.AddFrame(frames[i]); });
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(writer.FrameCount(), 3u);
  writer.Finish();

  const std::vector<BopScene> scenes = ListBopScenes(dir.path());
  ASSERT_EQ(scenes.size(), 1u);
  EXPECT_EQ(scenes[0].scene_id, 1);
  EXPECT_EQ(scenes[0].image_ids, (std::vector<int>{0, 1, 10}));
  for (const BopFrame& expected : frames) {
    const BopFrame frame = LoadBopFrame(scenes[0], expected.image_id);
    EXPECT_EQ(cv::norm(frame.color, expected.color, cv::NORM_INF), 0.0);
    EXPECT_EQ(cv::norm(frame.depth_mm, expected.depth_mm, cv::NORM_INF), 0.0);
    EXPECT_EQ(frame.camera, expected.camera);
    ASSERT_EQ(frame.gt.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(frame.gt[i].obj_id, expected.gt[i].obj_id);
      EXPECT_EQ(frame.gt[i].cam_from_model.R, expected.gt[i].cam_from_model.R);  // bit for bit
      EXPECT_EQ(frame.gt[i].cam_from_model.t, expected.gt[i].cam_from_model.t);
      EXPECT_EQ(frame.gt_info[i].bbox_obj, expected.gt_info[i].bbox_obj);
      EXPECT_EQ(frame.gt_info[i].bbox_visib, expected.gt_info[i].bbox_visib);
      EXPECT_EQ(frame.gt_info[i].px_count_all, expected.gt_info[i].px_count_all);
      EXPECT_EQ(frame.gt_info[i].px_count_valid, 900);
      EXPECT_EQ(frame.gt_info[i].px_count_visib, 0);
      EXPECT_EQ(frame.gt_info[i].visib_fract, 1.0 / 3.0);
    }
  }
}

TEST(BopWriterTest, DepthScaleKeepsSubMillimetreDepth) {
  test::TempDir dir;
  std::mt19937_64 rng(3);
  BopFrame frame = RandomFrame(4, rng);
  frame.depth_mm.setTo(123.4f);
  frame.depth_mm.at<float>(0, 0) = 0.0f;
  BopSceneWriter writer(dir / "000003", 0.1);
  writer.AddFrame(frame);
  writer.Finish();
  const BopFrame read = LoadBopFrame(LoadBopScene(dir / "000003"), 4);
  EXPECT_NEAR(read.depth_mm.at<float>(5, 5), 123.4f, 1e-4);
  EXPECT_EQ(read.depth_mm.at<float>(0, 0), 0.0f);
}

TEST(BopWriterTest, NothingIsReadableBeforeFinish) {
  test::TempDir dir;
  std::mt19937_64 rng(1);
  BopSceneWriter writer(dir / "000001");
  writer.AddFrame(RandomFrame(0, rng));
  EXPECT_TRUE(fs::exists(dir / "000001" / "rgb" / "000000.png"));
  EXPECT_TRUE(fs::exists(dir / "000001" / "depth" / "000000.png"));
  EXPECT_THROW(LoadBopScene(dir / "000001"), IoError);
}

TEST(BopWriterTest, RefusesBadFrames) {
  test::TempDir dir;
  std::mt19937_64 rng(1);
  BopSceneWriter writer(dir / "000001");
  writer.AddFrame(RandomFrame(0, rng));
  EXPECT_THAT(ThrownMessage<Error>([&] { writer.AddFrame(RandomFrame(0, rng)); }),
              HasSubstr("image 0 added twice"));
  BopFrame grey = RandomFrame(1, rng);
  grey.color = cv::Mat(60, 80, CV_8U, 3);
  EXPECT_THAT(ThrownMessage<Error>([&] { writer.AddFrame(grey); }), HasSubstr("BGR8"));
  BopFrame small_depth = RandomFrame(2, rng);
  small_depth.depth_mm = cv::Mat(10, 10, CV_32F, 1.0f);
  EXPECT_THAT(ThrownMessage<Error>([&] { writer.AddFrame(small_depth); }),
              HasSubstr("CV_32F of the colour image's size"));
  BopFrame no_depth = RandomFrame(3, rng);
  no_depth.depth_mm.release();
  EXPECT_THAT(ThrownMessage<Error>([&] { writer.AddFrame(no_depth); }),
              HasSubstr("must have depth, or none"));
  BopFrame short_info = RandomFrame(4, rng);
  short_info.gt_info.pop_back();
  EXPECT_THAT(ThrownMessage<Error>([&] { writer.AddFrame(short_info); }),
              HasSubstr("one entry per gt instance"));
  EXPECT_THROW(BopSceneWriter(dir / "x", 0.0), Error);
}

TEST(BopWriterTest, CameraFileRoundTrips) {
  test::TempDir dir;
  WriteBopCamera(dir / "camera.json", test::ManyDigitsCamera());
  EXPECT_EQ(LoadCameraJson(dir / "camera.json"), test::ManyDigitsCamera());
}

}  // namespace
}  // namespace layermod
