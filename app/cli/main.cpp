// SPDX-License-Identifier: MIT
// layermod: command-line front end of the LayerMOD core. Parses arguments and calls the core.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "cli/bench_command.h"
#include "cli/commands.h"
#include "cli/eval_command.h"
#include "util/error.h"
#include "util/log.h"
#include "util/version.h"

namespace {

constexpr int kExitError = 1;
constexpr int kExitUsage = 2;
constexpr int kExitCancelled = 130;

void LogToStderr(layermod::LogLevel level, std::string_view message) {
  if (level == layermod::LogLevel::kDebug) return;
  std::fprintf(stderr, "layermod: %s: %.*s\n", std::string(layermod::LogLevelName(level)).c_str(),
               static_cast<int>(message.size()), message.data());
}

// CLI11 reports a mistyped command as "a subcommand is required"; name it instead.
bool IsUnknownCommand(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->check_name(argv[1])) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  layermod::SetLogSink(LogToStderr);
  CLI::App app{
      "LayerMOD: multi-scale LineMOD templates and Scene-Patch detection for "
      "texture-less parts in RGB-D images"};
  app.set_version_flag("--version", "layermod " + layermod::ToolVersion());
  app.require_subcommand(1);
  layermod::cli::AddTrainCommand(app);
  layermod::cli::AddInspectCommand(app);
  layermod::cli::AddRenderCommand(app);
  layermod::cli::AddDetectCommand(app);
  layermod::cli::AddSynthCommand(app);
  layermod::cli::AddMakeSampleCommand(app);
  layermod::cli::AddEvalCommand(app);
  layermod::cli::AddBenchCommand(app);
  if (IsUnknownCommand(app, argc, argv)) {
    std::fprintf(stderr, "layermod: unknown command '%s' (see layermod --help)\n", argv[1]);
    return kExitUsage;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : kExitUsage;
  } catch (const layermod::Cancelled&) {
    std::fprintf(stderr, "layermod: cancelled; nothing was written\n");
    return kExitCancelled;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "layermod: error: %s\n", error.what());
    return kExitError;
  }
  return 0;
}
