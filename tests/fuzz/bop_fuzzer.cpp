// SPDX-License-Identifier: MIT
// Fuzz target: the BOP dataset reader, as `layermod eval` and `detect --bop` use it. Input:
// scene_camera.json, scene_gt.json, scene_gt_info.json, models_info.json, rgb and depth of the
// scene's first image, joined by fuzz::kPartSeparator (an empty part is an absent file).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "dataset/bop.h"
#include "dataset/models_info.h"
#include "fuzz/fuzz_input.h"
#include "util/error.h"

namespace {
namespace fs = std::filesystem;

void WriteIfPresent(const std::string& name, std::string_view bytes) {
  if (!bytes.empty()) layermod::fuzz::WriteScratchFile(name, bytes);
}

void LoadSceneAndFirstFrame(const std::vector<std::string_view>& parts) {
  using namespace layermod;
  const fs::path scene_dir = fuzz::ScratchDir() / "000001";
  fs::create_directories(scene_dir / "rgb");
  WriteIfPresent("000001/scene_camera.json", parts[0]);
  WriteIfPresent("000001/scene_gt.json", parts[1]);
  WriteIfPresent("000001/scene_gt_info.json", parts[2]);
  const BopScene scene = LoadBopScene(scene_dir);
  if (scene.image_ids.empty()) return;
  const std::string stem = BopIdName(scene.image_ids.front());
  WriteIfPresent("000001/rgb/" + stem + ".png", parts[4]);
  if (!parts[5].empty()) WriteIfPresent("000001/depth/" + stem + ".png", parts[5]);
  // has_depth was decided when the scene was listed; reload so that the depth folder counts.
  const BopScene with_images = LoadBopScene(scene_dir);
  LoadBopFrame(with_images, with_images.image_ids.front());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace layermod;
  fuzz::QuietLogsOnce();
  fuzz::ClearScratchDir();
  const auto parts = fuzz::SplitParts(fuzz::AsText(data, size), 6);
  const std::string scratch = fuzz::ScratchDir().string();
  fuzz::LoadOrNameTheFile([&] { LoadSceneAndFirstFrame(parts); }, scratch);
  fuzz::LoadOrNameTheFile(
      [&] { LoadModelsInfo(fuzz::WriteScratchFile("models/models_info.json", parts[3])); },
      scratch);
  return 0;
}
