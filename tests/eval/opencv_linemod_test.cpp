// SPDX-License-Identifier: MIT
#include "eval/opencv_linemod.h"

#include <gtest/gtest.h>

#include "eval/pose_metrics.h"
#include "eval_fixtures.h"
#include "render/rasterizer.h"
#include "support/matchers.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

class OpenCvLinemodTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    data_ = new test::TinyEvalData(test::MakeTinyEvalData(dir_->path(), 1));
    archives_ = new std::vector<TemplateArchive>{data_->archive};
  }
  static void TearDownTestSuite() {
    delete archives_;
    delete data_;
    delete dir_;
    archives_ = nullptr;
    data_ = nullptr;
    dir_ = nullptr;
  }

  static test::TempDir* dir_;
  static test::TinyEvalData* data_;
  static std::vector<TemplateArchive>* archives_;
};
test::TempDir* OpenCvLinemodTest::dir_ = nullptr;
test::TinyEvalData* OpenCvLinemodTest::data_ = nullptr;
std::vector<TemplateArchive>* OpenCvLinemodTest::archives_ = nullptr;

TEST_F(OpenCvLinemodTest, TakesOrRefusesEveryArchiveTemplate) {
  const OpenCvLinemod linemod({&archives_->front()}, {});
  EXPECT_EQ(static_cast<std::size_t>(linemod.training().templates + linemod.training().refused),
            data_->archive.templates().size());
  EXPECT_EQ(linemod.training().template_ids.size(),
            static_cast<std::size_t>(linemod.training().templates));
  EXPECT_GT(linemod.training().templates, 0);
}

// A scene that is exactly one trained template (same render, same pose, full image) must be
// found as that template, at its own box and pose: this checks the box bookkeeping between the
// two libraries. One depth layer, so no other layer's template can tie with it.
TEST(OpenCvLinemodSingleLayerTest, FindsATemplateRenderAtItsOwnPoseAndBox) {
  const std::vector<TemplateArchive> archives = {test::TrainBracketArchive(900.0, 910.0)};
  const TemplateArchive& archive = archives.front();
  ASSERT_EQ(archive.Object(1).layer_depths_mm.size(), 1u);
  const OpenCvLinemod linemod({&archive}, {});
  const std::vector<std::uint32_t>& taken = linemod.training().template_ids;
  ASSERT_GE(taken.size(), 2u);
  for (const std::uint32_t id : {taken.front(), taken[taken.size() / 2]}) {
    const TemplateRecord& record = archive.templates()[id];
    const ArchiveObject& object = archive.Object(record.obj_id);
    RenderOptions full;
    full.window = RenderWindow::kFullImage;
    const RenderedView scene =
        RenderView(object.mesh, archive.camera(), record.cam_from_model, full);
    const std::vector<Detection> detections = linemod.Detect(scene.color, scene.depth_mm);
    ASSERT_EQ(detections.size(), 1u);
    EXPECT_EQ(detections[0].template_id, record.id);
    EXPECT_GE(detections[0].score, 99.0f);
    EXPECT_LE(std::abs(detections[0].box_tl_px.x - record.bbox_px.x), 1);
    EXPECT_LE(std::abs(detections[0].box_tl_px.y - record.bbox_px.y), 1);
    EXPECT_THAT(detections[0].cam_from_model, test::PoseNear(record.cam_from_model, 0.01, 5.0));
  }
}

TEST_F(OpenCvLinemodTest, ColourOnlyNeedsNoDepthAndDepthModeDoes) {
  OpenCvLinemodOptions line2d;
  line2d.use_depth = false;
  const OpenCvLinemod colour_only({&archives_->front()}, line2d);
  const PinholeCamera& camera = data_->archive.camera();
  const cv::Mat black(camera.height, camera.width, CV_8UC3, cv::Scalar::all(0));
  EXPECT_TRUE(colour_only.Detect(black, {}).empty());
  const OpenCvLinemod with_depth({&archives_->front()}, {});
  EXPECT_THROW(with_depth.Detect(black, {}), Error);
}

TEST(OpenCvLinemodOptionsTest, Validates) {
  OpenCvLinemodOptions options;
  options.threshold_percent = 0.0f;
  EXPECT_THROW(options.Validate(), Error);
  EXPECT_THROW(OpenCvLinemod({}, {}), Error);
}

}  // namespace
}  // namespace layermod
