// SPDX-License-Identifier: MIT
// Integration: train the bundled sample, write the archive, read it back, compare.
#include "pipeline/training.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_cameras.h"
#include "support/test_paths.h"
#include "templates/archive.h"
#include "util/error.h"

namespace layermod {
namespace {

TrainingRequest TinyRequest() {
  TrainingRequest request;
  request.obj_id = 3;
  request.name = "bracket";
  request.camera = test::VgaCamera();
  request.profile.depth_min_mm = 600.0;
  request.profile.depth_max_mm = 900.0;
  request.profile.views.even_spacing_deg = 0.0;
  request.profile.views.azimuth = {0.0, 90.0, 270.0};
  request.profile.views.elevation = {15.0, 15.0, 45.0};
  request.profile.views.roll = {-20.0, 20.0, 20.0};
  return request;
}

const Model& SampleModel() {
  static const Model model = LoadModel(test::SourceDir() / "resources/sample/bracket.ply");
  return model;
}

void ExpectSameTemplate(const TemplateRecord& a, const TemplateRecord& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.obj_id, b.obj_id);
  EXPECT_EQ(a.layer_index, b.layer_index);
  EXPECT_EQ(a.layer_depth_mm, b.layer_depth_mm);
  EXPECT_EQ(a.view.azimuth_deg, b.view.azimuth_deg);
  EXPECT_EQ(a.view.elevation_deg, b.view.elevation_deg);
  EXPECT_EQ(a.view.roll_deg, b.view.roll_deg);
  EXPECT_TRUE(a.cam_from_model.R.isApprox(b.cam_from_model.R, 1e-12));
  EXPECT_TRUE(a.cam_from_model.t.isApprox(b.cam_from_model.t, 1e-12));
  EXPECT_EQ(a.bbox_px, b.bbox_px);
  EXPECT_EQ(a.centre_offset_px, b.centre_offset_px);
  EXPECT_EQ(a.centre_minus_surface_mm, b.centre_minus_surface_mm);
  EXPECT_EQ(a.depth_edge_count, b.depth_edge_count);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.levels, b.levels);
}

TEST(TrainingTest, PlanMatchesLayersAndViews) {
  const TrainingPlan plan = PlanTraining(SampleModel(), TinyRequest());
  EXPECT_EQ(plan.views.size(), 4u * 3u * 3u);
  EXPECT_NEAR(plan.radius_mm, SampleModel().sphere.radius_mm, 1e-9);
  // 300 mm range with step r: ceil(300 / r) layers.
  EXPECT_EQ(plan.layer_depths_mm.size(),
            static_cast<std::size_t>(std::ceil(300.0 / SampleModel().sphere.radius_mm)));
}

TEST(TrainingTest, TrainsWritesAndReloadsIdentically) {
  const TrainingResult result = TrainTemplates(SampleModel(), TinyRequest());
  const auto& templates = result.archive.templates();
  ASSERT_EQ(templates.size(), PlanTraining(SampleModel(), TinyRequest()).TemplateCount());
  EXPECT_EQ(result.summary.weak_templates, 0u);
  for (std::size_t i = 0; i < templates.size(); ++i) {
    EXPECT_EQ(templates[i].id, i);
    EXPECT_GE(templates[i].FeatureCount(), 60);
    EXPECT_GT(templates[i].depth_edge_count, 0);
  }
  test::TempDir dir;
  WriteArchive(dir / "bracket.layermod", result.archive);
  const TemplateArchive loaded = ReadArchive(dir / "bracket.layermod");
  ASSERT_EQ(loaded.templates().size(), templates.size());
  for (std::size_t i = 0; i < templates.size(); ++i) {
    ExpectSameTemplate(loaded.templates()[i], templates[i]);
  }
  EXPECT_EQ(loaded.camera(), test::VgaCamera());
  const ArchiveObject& object = loaded.Object(3);
  EXPECT_EQ(object.name, "bracket");
  EXPECT_NEAR(object.sphere.radius_mm, SampleModel().sphere.radius_mm, 1e-9);
  EXPECT_EQ(object.profile.views, TinyRequest().profile.views);
  EXPECT_EQ(loaded.TemplatesOf(3, 0).size(), 36u);
}

TEST(TrainingTest, TrainingIsDeterministicAcrossThreadCounts) {
  TrainingRequest one_thread = TinyRequest();
  one_thread.threads = 1;
  const TrainingResult a = TrainTemplates(SampleModel(), one_thread);
  const TrainingResult b = TrainTemplates(SampleModel(), TinyRequest());
  ASSERT_EQ(a.archive.templates().size(), b.archive.templates().size());
  for (std::size_t i = 0; i < a.archive.templates().size(); ++i) {
    ExpectSameTemplate(a.archive.templates()[i], b.archive.templates()[i]);
  }
}

TEST(TrainingTest, CancelledTrainingThrowsCancelled) {
  CancelToken token;
  token.Cancel();
  EXPECT_THROW(TrainTemplates(SampleModel(), TinyRequest(), JobControl({}, &token)), Cancelled);
}

TEST(TrainingTest, ReportsProgressUpToTheTotal) {
  std::size_t last_done = 0;
  std::size_t last_total = 0;
  const JobControl job(
      [&](std::size_t done, std::size_t total, std::string_view) {
        last_done = std::max(last_done, done);
        last_total = total;
      },
      nullptr);
  TrainTemplates(SampleModel(), TinyRequest(), job);
  EXPECT_EQ(last_done, last_total);
  EXPECT_EQ(last_total, PlanTraining(SampleModel(), TinyRequest()).TemplateCount());
}

TEST(TrainingTest, RejectsBadRequests) {
  TrainingRequest request = TinyRequest();
  request.profile.depth_min_mm = 900.0;
  request.profile.depth_max_mm = 600.0;
  EXPECT_THROW(PlanTraining(SampleModel(), request), Error);
  request = TinyRequest();
  request.profile.depth_min_mm = 10.0;  // camera inside the part
  EXPECT_THROW(PlanTraining(SampleModel(), request), Error);
  request = TinyRequest();
  request.camera.fx = 0.0;
  EXPECT_THROW(PlanTraining(SampleModel(), request), Error);
  request = TinyRequest();
  request.profile.views.roll.step_deg = 0.0;
  EXPECT_THROW(PlanTraining(SampleModel(), request), Error);
}

TEST(TrainingTest, RunsTooLargeForMemoryAreRefusedUpFrontWithTheEstimate) {
  TrainingRequest request = TinyRequest();
  request.profile.depth_min_mm = 300.0;
  request.profile.depth_max_mm = 30000.0;  // 437 layers for the bracket
  request.profile.views.azimuth = {0.0, 0.1, 359.9};
  request.profile.views.elevation = {0.0, 0.1, 90.0};
  request.profile.views.roll = {-45.0, 1.0, 45.0};
  try {
    PlanTraining(SampleModel(), request);
    FAIL() << "a run of 10^11 templates was planned";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("MiB of memory"));
    EXPECT_THAT(error.what(), ::testing::HasSubstr("reduce the depth range or the view sampling"));
  }
  EXPECT_LE(TrainingMemoryLimitBytes(), std::size_t{8} << 30);
  EXPECT_GT(TrainingMemoryLimitBytes(), std::size_t{0});
}

}  // namespace
}  // namespace layermod
