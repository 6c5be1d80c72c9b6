// SPDX-License-Identifier: MIT
// Fuzz target: mesh import (assimp + cleaning + sphere), as `layermod train --model` does. The
// first byte picks the file extension, the rest is the file.
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input.h"
#include "mesh/model.h"
#include "util/error.h"

namespace {

void CheckLoadedModel(const layermod::Model& model) {
  if (model.mesh.n_faces() == 0 || !std::isfinite(model.sphere.radius_mm) ||
      model.sphere.radius_mm < 0) {
    std::abort();
  }
  for (const auto vertex : model.mesh.vertices()) {
    const auto& point = model.mesh.point(vertex);
    const double distance =
        (Eigen::Vector3d(point[0], point[1], point[2]) - model.sphere.centre).norm();
    if (!(distance <= model.sphere.radius_mm * (1.0 + 1e-6) + 1e-6))
      std::abort();  // sphere encloses
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace layermod;
  fuzz::QuietLogsOnce();
  if (size == 0) return 0;
  static constexpr std::array<const char*, 4> kExtensions = {"ply", "stl", "obj", "off"};
  fuzz::ClearScratchDir();
  const auto path = fuzz::WriteScratchFile(std::string("mesh.") + kExtensions[data[0] % 4],
                                           fuzz::AsText(data + 1, size - 1));
  LoadModelOptions options;
  options.max_triangles = 200'000;  // keeps each input fast; the limit itself is tested too
  // An assimp hang is contained by the helper's timeout (an error naming the file); shortened
  // here so that containment happens well inside libFuzzer's per-input timeout.
  options.import_timeout = std::chrono::seconds(5);
  fuzz::LoadOrNameTheFile(
      [&] {
        Model model = LoadModel(path, options);
        CheckLoadedModel(model);
        RecentreOnSphere(model);
        ToRenderMesh(model);
      },
      path.string());
  return 0;
}
