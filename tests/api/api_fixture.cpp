// SPDX-License-Identifier: MIT
#include "api_fixture.h"

#include <layermod/training.h>

#include "dataset/bop.h"
#include "support/test_paths.h"
#include "synth/synthesizer.h"

namespace layermod::test {
namespace {

constexpr char kProfile[] =
    R"({"depth_min_mm": 600, "depth_max_mm": 900,
        "views": {"even_spacing_deg": 20,
                  "roll": {"min_deg": -30, "step_deg": 15, "max_deg": 30}}})";

ApiSample MakeSample() {
  static TempDir dir;  // lives as long as the process
  api::TrainOptions train;
  train.model = SampleDir() / "bracket.ply";
  train.obj_id = 1;
  train.name = "bracket";
  train.camera = api::Camera::FromJson(SampleDir() / "camera.json");
  train.profile_json = kProfile;
  train.out = dir / "bracket.layermod";
  ApiSample sample{api::Train(train), train.out, {}};

  SynthOptions synth;
  synth.models_dir = SampleDir() / "bracket.ply";
  synth.obj_ids = {1};
  synth.scenes = 3;
  synth.seed = 1;
  synth.dmin_mm = 650.0;
  synth.dmax_mm = 850.0;
  synth.camera = LoadCameraJson(SampleDir() / "camera.json");
  synth.out_dir = dir / "scenes";
  SynthesizeScenes(synth);
  for (const BopScene& scene : ListBopScenes(synth.out_dir / "test")) {
    for (int image_id : scene.image_ids) {
      const BopFrame frame = LoadBopFrame(scene, image_id);
      const std::filesystem::path name = BopIdName(image_id) + ".png";
      sample.frames.push_back(
          {api::LoadCapture(scene.dir / "rgb" / name, scene.dir / "depth" / name,
                            SampleDir() / "camera.json"),
           frame.gt.at(0).cam_from_model.t});
    }
  }
  return sample;
}

}  // namespace

std::filesystem::path SampleDir() { return SourceDir() / "resources" / "sample"; }

const ApiSample& Sample() {
  static const ApiSample sample = MakeSample();
  return sample;
}

}  // namespace layermod::test
