// SPDX-License-Identifier: MIT
#include "eval_fixtures.h"

#include "mesh/model.h"
#include "pipeline/training.h"
#include "render/rasterizer.h"
#include "support/test_paths.h"
#include "synth/synthesizer.h"
#include "synth_fixtures.h"

namespace layermod::test {

namespace {

constexpr float kBackgroundBehindMm = 150.0f;  // a wall this far behind the part

TrainingRequest SmallRequest(double dmin_mm, double dmax_mm) {
  TrainingRequest request;
  request.obj_id = 1;
  request.name = "bracket";
  request.camera = SmallCamera();
  request.profile.depth_min_mm = dmin_mm;
  request.profile.depth_max_mm = dmax_mm;
  request.profile.views.even_spacing_deg = 0.0;
  request.profile.views.azimuth = {0.0, 60.0, 300.0};
  request.profile.views.elevation = {20.0, 30.0, 80.0};
  request.profile.views.roll = {0.0, 10.0, 0.0};
  request.threads = 2;
  return request;
}

}  // namespace

Capture CaptureAtTemplatePose(const TemplateArchive& archive, const TemplateRecord& record) {
  const PinholeCamera& camera = archive.camera();
  const RenderedView view =
      RenderView(archive.Object(record.obj_id).mesh, camera, record.cam_from_model);
  Capture capture;
  capture.camera = camera;
  capture.color = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar(70, 80, 90));
  capture.depth_mm = cv::Mat(camera.height, camera.width, CV_32F,
                             cv::Scalar(record.layer_depth_mm + kBackgroundBehindMm));
  view.color.copyTo(capture.color(view.roi), view.mask);
  view.depth_mm.copyTo(capture.depth_mm(view.roi), view.mask);
  return capture;
}

TemplateArchive TrainBracketArchive(double dmin_mm, double dmax_mm) {
  static const Model model = LoadModel(SourceDir() / "resources/sample/bracket.ply");
  return TrainTemplates(model, SmallRequest(dmin_mm, dmax_mm)).archive;
}

TinyEvalData MakeTinyEvalData(const std::filesystem::path& dir, int images) {
  const std::filesystem::path models = WriteBracketModels(dir);
  TinyEvalData data;
  data.dataset = dir / "data";
  SynthOptions options = SmallOptions(models, {1}, images, data.dataset);
  SynthesizeScenes(options);
  data.archive = TrainBracketArchive(600.0, 1200.0);
  data.archive_file = dir / "bracket.layermod";
  WriteArchive(data.archive_file, data.archive);
  return data;
}

}  // namespace layermod::test
