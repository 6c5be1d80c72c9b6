// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/CLI.hpp>

namespace layermod::cli {

// Each command registers its flags and a callback that does the work. Callbacks throw
// layermod::Error (exit 1) or layermod::Cancelled (exit 130); main() turns them into messages.
void AddTrainCommand(CLI::App& app);
void AddInspectCommand(CLI::App& app);
void AddRenderCommand(CLI::App& app);
void AddMakeSampleCommand(CLI::App& app);
void AddSynthCommand(CLI::App& app);
void AddDetectCommand(CLI::App& app);

}  // namespace layermod::cli
