// SPDX-License-Identifier: MIT
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "bop_fixtures.h"
#include "dataset/bop.h"
#include "support/matchers.h"
#include "support/test_paths.h"
#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

using test::ThrownMessage;

std::optional<fs::path> LmoDev() {
  const auto data = test::SharedDataDir();
  if (!data || !fs::is_directory(*data / "lmo-dev" / "test" / "000002")) return std::nullopt;
  return *data / "lmo-dev";
}

TEST(BopReaderTest, ListsTheRealLmoSceneFromTheSplitAndFromTheRoot) {
  const auto lmo = LmoDev();
  if (!lmo) GTEST_SKIP() << "shared data (lmo-dev) not found; set LAYERMOD_DATA_DIR";
  for (const fs::path& dir : {*lmo / "test", *lmo}) {
    const std::vector<BopScene> scenes = ListBopScenes(dir);
    ASSERT_EQ(scenes.size(), 1u);
    EXPECT_EQ(scenes[0].scene_id, 2);
    EXPECT_EQ(scenes[0].image_ids.size(), 100u);
    EXPECT_EQ(scenes[0].image_ids.front(), 3);
    EXPECT_TRUE(std::is_sorted(scenes[0].image_ids.begin(), scenes[0].image_ids.end()));
    EXPECT_FALSE(scenes[0].has_depth);
    EXPECT_TRUE(scenes[0].has_gt_info);
  }
}

TEST(BopReaderTest, RealFrameThreeHasTheGroundTruthOfTheApe) {
  const auto lmo = LmoDev();
  if (!lmo) GTEST_SKIP() << "shared data (lmo-dev) not found; set LAYERMOD_DATA_DIR";
  const BopScene scene = LoadBopScene(*lmo / "test" / "000002");
  const BopFrame frame = LoadBopFrame(scene, 3);
  EXPECT_EQ(frame.scene_id, 2);
  EXPECT_EQ(frame.image_id, 3);
  EXPECT_EQ(frame.color.type(), CV_8UC3);
  EXPECT_EQ(frame.color.size(), cv::Size(640, 480));
  EXPECT_TRUE(frame.depth_mm.empty());  // lmo-dev has no depth
  EXPECT_DOUBLE_EQ(frame.camera.fx, 572.4114);
  EXPECT_DOUBLE_EQ(frame.camera.fy, 573.57043);
  EXPECT_DOUBLE_EQ(frame.camera.cx, 325.2611);
  EXPECT_DOUBLE_EQ(frame.camera.cy, 242.04899);
  EXPECT_EQ(frame.camera.width, 640);
  EXPECT_EQ(frame.camera.height, 480);

  ASSERT_FALSE(frame.gt.empty());
  ASSERT_EQ(frame.gt_info.size(), frame.gt.size());
  const BopGroundTruth& ape = frame.gt[0];
  EXPECT_EQ(ape.obj_id, 1);
  Eigen::Matrix3d rotation;
  rotation << 0.87547542, 0.47867615, -0.06858282, 0.3746311, -0.76110463, -0.52974822, -0.30574968,
      0.43803819, -0.84552592;
  EXPECT_EQ(ape.cam_from_model.R, rotation);
  EXPECT_EQ(ape.cam_from_model.t, Eigen::Vector3d(161.68945982, -113.74032768, 1112.83112737));
  const BopGtInfo& info = frame.gt_info[0];
  EXPECT_EQ(info.bbox_obj, cv::Rect(388, 164, 34, 45));
  EXPECT_EQ(info.bbox_visib, cv::Rect(401, 164, 20, 33));
  EXPECT_EQ(info.px_count_all, 1127);
  EXPECT_EQ(info.px_count_valid, 1105);
  EXPECT_EQ(info.px_count_visib, 225);
  EXPECT_DOUBLE_EQ(info.visib_fract, 0.19964507542147295);
}

class TinySceneTest : public ::testing::Test {
 protected:
  void SetUp() override { scene_dir_ = test::WriteTinyScene(dir_.path()); }

  // Replaces one file of the scene and returns the LoadBopScene error message (type E).
  template <typename E>
  std::string LoadWith(const std::string& name, const std::string& text) {
    test::WriteText(scene_dir_ / name, text);
    return ThrownMessage<E>([&] { LoadBopScene(scene_dir_); });
  }

  test::TempDir dir_;
  fs::path scene_dir_;
};

TEST_F(TinySceneTest, ReadsColourDepthCameraAndAnnotations) {
  const BopScene scene = LoadBopScene(scene_dir_);
  EXPECT_EQ(scene.scene_id, 2);
  EXPECT_EQ(scene.image_ids, (std::vector<int>{0, 5}));
  EXPECT_TRUE(scene.has_depth);
  const BopFrame frame = LoadBopFrame(scene, 5);
  EXPECT_EQ(frame.color.at<cv::Vec3b>(0, 0), cv::Vec3b(10, 20, 30));
  ASSERT_EQ(frame.depth_mm.type(), CV_32F);
  EXPECT_FLOAT_EQ(frame.depth_mm.at<float>(7, 3), 510.0f);
  EXPECT_EQ(frame.camera.width, 64);
  EXPECT_DOUBLE_EQ(frame.camera.cy, 23.5);
  ASSERT_EQ(frame.gt.size(), 1u);
  EXPECT_EQ(frame.gt[0].obj_id, 7);
  EXPECT_EQ(frame.gt[0].cam_from_model.t, Eigen::Vector3d(1.5, -2.25, 700.125));
  EXPECT_EQ(frame.gt_info[0].px_count_valid, 90);
}

TEST_F(TinySceneTest, DepthIsScaledToMillimetres) {
  test::WriteText(scene_dir_ / "scene_camera.json", test::SceneCameraJson("0,5", "", "0.1"));
  const BopFrame frame = LoadBopFrame(LoadBopScene(scene_dir_), 0);
  EXPECT_FLOAT_EQ(frame.depth_mm.at<float>(0, 0), 50.0f);
}

TEST_F(TinySceneTest, UnknownImageIdNamesTheSceneAndFolder) {
  const BopScene scene = LoadBopScene(scene_dir_);
  EXPECT_EQ(ThrownMessage<Error>([&] { LoadBopFrame(scene, 42); }),
            "image 42 is not in scene 2 ('" + scene_dir_.string() + "')");
}

TEST_F(TinySceneTest, MissingSceneFilesAreNamed) {
  fs::remove(scene_dir_ / "scene_gt.json");
  EXPECT_THAT(
      ThrownMessage<IoError>([&] { LoadBopScene(scene_dir_); }),
      AllOf(HasSubstr((scene_dir_ / "scene_gt.json").string()), HasSubstr("missing scene file")));
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadBopScene(dir_ / "nowhere"); }),
              HasSubstr("scene folder does not exist"));
}

TEST_F(TinySceneTest, MalformedJsonIsAFormatError) {
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", "{\"0\": [ {"),
              AllOf(HasSubstr("scene_gt.json"), HasSubstr("malformed JSON")));
  EXPECT_THAT(LoadWith<FormatError>("scene_camera.json", "[1, 2]"), HasSubstr("not a JSON object"));
}

TEST_F(TinySceneTest, WrongCameraFieldsAreNamed) {
  EXPECT_THAT(LoadWith<FormatError>("scene_camera.json",
                                    test::SceneCameraJson("0,5", "[60, 0, 31.5, 0, 61]")),
              AllOf(HasSubstr("scene_camera.json"), HasSubstr("image 0"),
                    HasSubstr("'cam_K' must be 9 numbers")));
  EXPECT_THAT(
      LoadWith<FormatError>("scene_camera.json",
                            test::SceneCameraJson("0,5", "[60,0,31.5,0,61,23.5,0,0,\"1\"]")),
      HasSubstr("'cam_K' must be 9 numbers"));
  EXPECT_THAT(LoadWith<FormatError>("scene_camera.json", test::SceneCameraJson("0,5", "", "0")),
              HasSubstr("'depth_scale' must be positive"));
  EXPECT_THAT(LoadWith<FormatError>("scene_camera.json", test::SceneCameraJson("0,5", "", "-1")),
              HasSubstr("'depth_scale' must be positive"));
  EXPECT_THAT(LoadWith<FormatError>("scene_camera.json", "{\"x\": {}}"),
              HasSubstr("key 'x' is not a non-negative integer id"));
}

TEST_F(TinySceneTest, WrongPoseFieldsAreNamed) {
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", test::SceneGtJson("0,5", "[1, 0, 0]")),
              AllOf(HasSubstr("scene_gt.json"), HasSubstr("instance 0"),
                    HasSubstr("'cam_R_m2c' must be 9 numbers")));
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", test::SceneGtJson("0,5", "", "[1, 2]")),
              HasSubstr("'cam_t_m2c' must be 3 numbers"));
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", "{\"0\": [{\"cam_R_m2c\": [1]}]}"),
              HasSubstr("'obj_id' is missing"));
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", "{\"0\": {}}"),
              HasSubstr("expected a list of object instances"));
  EXPECT_THAT(LoadWith<FormatError>("scene_gt.json", test::SceneGtJson("0,9")),
              HasSubstr("image 9 is not in scene_camera.json"));
}

TEST_F(TinySceneTest, GtInfoMustMatchTheGroundTruth) {
  EXPECT_THAT(
      LoadWith<FormatError>("scene_gt_info.json", "{\"0\": []}"),
      AllOf(HasSubstr("scene_gt_info.json"), HasSubstr("0 entries but scene_gt.json has 1")));
  EXPECT_THAT(LoadWith<FormatError>("scene_gt_info.json", "{\"0\": [{\"bbox_obj\": [1, 2]}]}"),
              HasSubstr("'bbox_obj' must be 4 numbers"));
}

TEST_F(TinySceneTest, GtInfoIsOptional) {
  fs::remove(scene_dir_ / "scene_gt_info.json");
  const BopScene scene = LoadBopScene(scene_dir_);
  EXPECT_FALSE(scene.has_gt_info);
  EXPECT_TRUE(LoadBopFrame(scene, 0).gt_info.empty());
}

TEST_F(TinySceneTest, MissingOrBrokenImagesAreIoErrors) {
  const BopScene scene = LoadBopScene(scene_dir_);
  fs::remove(scene_dir_ / "rgb" / "000005.png");
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadBopFrame(scene, 5); }),
              AllOf(HasSubstr("000005.png"), HasSubstr("colour image is missing")));
  test::WriteText(scene_dir_ / "rgb" / "000000.png", "not a png");
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadBopFrame(scene, 0); }),
              AllOf(HasSubstr("rgb/000000.png"), HasSubstr("cannot decode")));
}

TEST_F(TinySceneTest, ReadsJpegColour) {
  fs::remove(scene_dir_ / "rgb" / "000005.png");
  cv::imwrite((scene_dir_ / "rgb" / "000005.jpg").string(),
              cv::Mat(48, 64, CV_8UC3, cv::Scalar(100, 100, 100)));
  const BopFrame frame = LoadBopFrame(LoadBopScene(scene_dir_), 5);
  EXPECT_EQ(frame.color.size(), cv::Size(64, 48));
}

TEST_F(TinySceneTest, DepthProblemsAreNamed) {
  const BopScene scene = LoadBopScene(scene_dir_);
  cv::imwrite((scene_dir_ / "depth" / "000000.png").string(), cv::Mat(48, 64, CV_8U, 7));
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadBopFrame(scene, 0); }),
              AllOf(HasSubstr("depth/000000.png"), HasSubstr("16-bit")));
  cv::imwrite((scene_dir_ / "depth" / "000000.png").string(), cv::Mat(40, 64, CV_16U, 7));
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadBopFrame(scene, 0); }),
              HasSubstr("depth is 64x40 but the colour image is 64x48"));
  fs::remove(scene_dir_ / "depth" / "000005.png");
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadBopFrame(scene, 5); }),
              AllOf(HasSubstr("depth/000005.png"), HasSubstr("missing")));
}

TEST_F(TinySceneTest, ListingErrors) {
  EXPECT_THAT(ThrownMessage<IoError>([&] { ListBopScenes(dir_ / "nowhere"); }),
              HasSubstr("folder does not exist"));
  fs::create_directories(dir_ / "empty");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { ListBopScenes(dir_ / "empty"); }),
              HasSubstr("no BOP scene folder"));
}

TEST(BopIdNameTest, SixDigits) {
  EXPECT_EQ(BopIdName(0), "000000");
  EXPECT_EQ(BopIdName(42), "000042");
}

}  // namespace
}  // namespace layermod
