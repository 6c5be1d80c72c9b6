// SPDX-License-Identifier: MIT
#include <cstdio>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "mesh/model.h"
#include "mesh/sample_part.h"

namespace layermod::cli {

void AddMakeSampleCommand(CLI::App& app) {
  auto out = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "make-sample", "Write the bundled sample part (a procedurally built bracket) as PLY");
  command->add_option("--out", *out, "Output mesh (*.ply)")->required();
  command->callback([out] {
    SaveModelPly(*out, MakeSampleBracket());
    std::printf("wrote %s\n", out->c_str());
  });
}

}  // namespace layermod::cli
