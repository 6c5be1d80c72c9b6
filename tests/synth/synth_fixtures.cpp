// SPDX-License-Identifier: MIT
#include "synth_fixtures.h"

#include "dataset/bop.h"
#include "mesh/model.h"
#include "mesh/sample_part.h"
#include "support/test_paths.h"

namespace layermod::test {
namespace fs = std::filesystem;

fs::path WriteBracketModels(const fs::path& dir) {
  const fs::path models = dir / "models";
  fs::create_directories(models);
  SaveModelPly(models / "obj_000001.ply", MakeSampleBracket());
  return models;
}

std::optional<fs::path> LinkLmoModels(const fs::path& dir, const std::vector<int>& obj_ids) {
  const auto data = SharedDataDir();
  if (!data) return std::nullopt;
  const fs::path source = *data / "lmo-dev" / "models";
  if (!fs::is_directory(source)) return std::nullopt;
  const fs::path models = dir / "lmo-models";
  fs::create_directories(models);
  fs::create_symlink(source / "models_info.json", models / "models_info.json");
  for (const int id : obj_ids) {
    fs::create_symlink(source / BopModelFileName(id), models / BopModelFileName(id));
  }
  return models;
}

SynthOptions SmallOptions(const fs::path& models_dir, const std::vector<std::int32_t>& obj_ids,
                          int scenes, const fs::path& out_dir) {
  SynthOptions options;
  options.models_dir = models_dir;
  options.obj_ids = obj_ids;
  options.scenes = scenes;
  options.seed = 7;
  options.camera = SmallCamera();
  options.out_dir = out_dir;
  options.threads = 2;
  return options;
}

}  // namespace layermod::test
