// SPDX-License-Identifier: MIT
// Fuzz target: loading an RGB-D capture (camera JSON + depth PNG + colour PNG), as
// `layermod detect --color --depth --camera` does. Input: the three files joined by
// fuzz::kPartSeparator.
#include <opencv2/core.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input.h"
#include "pipeline/capture_io.h"
#include "util/error.h"

namespace {

void CheckLoadedCapture(const layermod::Capture& capture) {
  if (capture.color.cols != capture.camera.width || capture.color.rows != capture.camera.height) {
    std::abort();
  }
  if (capture.color.type() != CV_8UC3) std::abort();
  if (capture.depth_mm.empty()) return;
  if (capture.depth_mm.size() != capture.color.size() || capture.depth_mm.type() != CV_32F) {
    std::abort();
  }
  capture.depth_mm.forEach<float>([](const float& value, const int*) {
    if (!std::isfinite(value) || value < 0.0f) std::abort();
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace layermod;
  fuzz::QuietLogsOnce();
  fuzz::ClearScratchDir();
  const auto parts = fuzz::SplitParts(fuzz::AsText(data, size), 3);
  CaptureFiles files;
  files.camera = fuzz::WriteScratchFile("camera.json", parts[0]);
  files.depth = fuzz::WriteScratchFile("depth.png", parts[1]);
  files.color = fuzz::WriteScratchFile("color.png", parts[2]);
  fuzz::LoadOrNameTheFile([&] { CheckLoadedCapture(LoadCapture(files)); },
                          fuzz::ScratchDir().string());
  return 0;
}
