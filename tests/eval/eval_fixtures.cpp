// SPDX-License-Identifier: MIT
#include "eval_fixtures.h"

#include "mesh/model.h"
#include "pipeline/training.h"
#include "synth/synthesizer.h"
#include "synth_fixtures.h"

namespace layermod::test {

namespace {

TrainingRequest SmallRequest() {
  TrainingRequest request;
  request.obj_id = 1;
  request.name = "bracket";
  request.camera = SmallCamera();
  request.profile.depth_min_mm = 600.0;
  request.profile.depth_max_mm = 1200.0;
  request.profile.views.even_spacing_deg = 0.0;
  request.profile.views.azimuth = {0.0, 60.0, 300.0};
  request.profile.views.elevation = {20.0, 30.0, 80.0};
  request.profile.views.roll = {0.0, 10.0, 0.0};
  request.threads = 2;
  return request;
}

}  // namespace

TinyEvalData MakeTinyEvalData(const std::filesystem::path& dir, int images) {
  const std::filesystem::path models = WriteBracketModels(dir);
  TinyEvalData data;
  data.dataset = dir / "data";
  SynthOptions options = SmallOptions(models, {1}, images, data.dataset);
  SynthesizeScenes(options);
  const Model model = LoadModel(models / "obj_000001.ply");
  data.archive = TrainTemplates(model, SmallRequest()).archive;
  data.archive_file = dir / "bracket.layermod";
  WriteArchive(data.archive_file, data.archive);
  return data;
}

}  // namespace layermod::test
