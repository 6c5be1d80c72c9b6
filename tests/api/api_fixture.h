// SPDX-License-Identifier: MIT
// The bundled sample part trained small through the public API, and three seeded synthetic
// RGB-D frames of it, made once per test process.
#pragma once

#include <layermod/archive.h>
#include <layermod/capture.h>

#include <Eigen/Core>
#include <filesystem>
#include <vector>

namespace layermod::test {

struct SampleFrame {
  api::Capture capture;  // depth CV_32F mm
  Eigen::Vector3d true_t_mm;
};

struct ApiSample {
  api::Archive archive;
  std::filesystem::path archive_path;
  std::vector<SampleFrame> frames;
};

// 5 layers 600-900 mm, 20 degree even views, roll -30..30; scenes 650-850 mm away.
const ApiSample& Sample();

// The sample archive is coarse for speed (20 degree views): its right poses fit the depth less
// closely than a default archive's and verify at confidences from about 0.75, below the default
// acceptance of 0.8.
inline constexpr char kSampleDetectorOptions[] = R"({"min_confidence": 0.5})";

std::filesystem::path SampleDir();  // resources/sample

}  // namespace layermod::test
