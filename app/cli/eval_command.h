// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace layermod::cli {

// `layermod eval`: accuracy and time of the detector on a BOP dataset (report.json + report.md).
void AddEvalCommand(CLI::App& app);

}  // namespace layermod::cli
