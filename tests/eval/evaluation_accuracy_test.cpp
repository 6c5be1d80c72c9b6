// SPDX-License-Identifier: MIT
// Accuracy end to end that needs no shared data: frames of the bundled bracket rendered at the
// poses of its own templates, written as a BOP dataset and evaluated. Every target is a pose a
// template matches exactly, so every one must be found and scored correct.
#include <gtest/gtest.h>

#include "dataset/bop_writer.h"
#include "dataset/models_info.h"
#include "eval/evaluation.h"
#include "eval_fixtures.h"
#include "mesh/model.h"
#include "support/test_paths.h"
#include "synth_fixtures.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 3;

// models/ (mesh and models_info.json) and test/000001 with one frame per chosen template.
fs::path WriteTemplatePoseDataset(const fs::path& root, const TemplateArchive& archive) {
  const fs::path models = test::WriteBracketModels(root);
  const Model model = LoadModel(models / "obj_000001.ply");
  ModelInfo info;
  info.obj_id = 1;
  info.diameter_mm = model.DiameterMm();
  WriteModelsInfo(models / "models_info.json", {{1, info}});
  BopSceneWriter writer(root / "test" / "000001");
  const auto& templates = archive.templates();
  for (int i = 0; i < kFrames; ++i) {
    const TemplateRecord& record = templates[(i + 1) * templates.size() / (kFrames + 1)];
    const Capture capture = test::CaptureAtTemplatePose(archive, record);
    BopFrame frame;
    frame.scene_id = 1;
    frame.image_id = i;
    frame.color = capture.color;
    frame.depth_mm = capture.depth_mm;
    frame.camera = capture.camera;
    frame.gt = {{1, record.cam_from_model}};
    writer.AddFrame(frame);
  }
  writer.Finish();
  return root;
}

TEST(EvaluationAccuracyTest, EveryBracketAtATemplatePoseIsFoundAndCorrect) {
  test::TempDir dir;
  TemplateArchive archive = test::TrainBracketArchive(650.0, 750.0);
  const fs::path dataset = WriteTemplatePoseDataset(dir.path(), archive);
  const Detector detector({std::move(archive)});
  DetectorOptions options;
  options.min_confidence = 0.0;  // accuracy of the best pose, as eval's recall counts it
  const Evaluation evaluation = Evaluate(detector, options, dataset, {}, {});
  ASSERT_EQ(evaluation.summary.objects.size(), 1u);
  const ObjectSummary& object = evaluation.summary.objects[0];
  EXPECT_EQ(object.frames, kFrames);
  EXPECT_EQ(object.detected, kFrames);
  EXPECT_EQ(object.correct, kFrames);
  for (const TargetOutcome& outcome : evaluation.run.outcomes) {
    EXPECT_LT(outcome.pose.error_mm, 0.05 * object.diameter_mm) << "image " << outcome.image_id;
  }
}

}  // namespace
}  // namespace layermod
