// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace layermod::cli {

// `layermod bench`: Scene-Patch vs exhaustive vs cv::linemod, same frames and templates.
void AddBenchCommand(CLI::App& app);

}  // namespace layermod::cli
