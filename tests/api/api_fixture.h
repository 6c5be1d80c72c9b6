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

std::filesystem::path SampleDir();  // resources/sample

}  // namespace layermod::test
