// SPDX-License-Identifier: MIT
// layermod-import-mesh: reads one mesh through assimp in its own process and writes the merged
// triangles to stdout (mesh/mesh_import.h), so that a reader crash or hang on a hostile file
// cannot take the CLI or the studio down. Errors: message on stderr, exit code by error type.
//   layermod-import-mesh --units mm|m --max-triangles N [--parent PID] -- FILE
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "mesh/mesh_import.h"
#include "util/error.h"

namespace {

layermod::MeshImportOptions ParseArgs(int argc, char** argv, std::string& path, pid_t& parent) {
  layermod::MeshImportOptions options;
  options.isolate = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--units" && i + 1 < argc) {
      options.units = std::string(argv[++i]) == "m" ? layermod::LengthUnit::kMetre
                                                    : layermod::LengthUnit::kMillimetre;
    } else if (arg == "--max-triangles" && i + 1 < argc) {
      options.max_triangles = std::strtoull(argv[++i], nullptr, 10);
    } else if (arg == "--parent" && i + 1 < argc) {
      parent = static_cast<pid_t>(std::strtol(argv[++i], nullptr, 10));
    } else if (arg == "--" && i + 2 == argc) {
      path = argv[i + 1];
      return options;
    } else {
      break;
    }
  }
  throw layermod::Error(
      "usage: layermod-import-mesh --units mm|m --max-triangles N [--parent PID] -- FILE");
}

// The helper lives only as long as the program that asked for the mesh (`--parent PID`): a
// reader caught in an endless loop must not outlive a caller killed before its timeout struck.
void DieWithParent(pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (parent > 0 && getppid() != parent) std::_Exit(layermod::kImporterError);  // already gone
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string path;
    pid_t parent = 0;
    const layermod::MeshImportOptions options = ParseArgs(argc, argv, path, parent);
    DieWithParent(parent);
    const std::string bytes = layermod::SerializeSoup(layermod::ImportTriangles(path, options));
    return std::fwrite(bytes.data(), 1, bytes.size(), stdout) == bytes.size() &&
                   std::fflush(stdout) == 0
               ? 0
               : layermod::kImporterIoError;
  } catch (const layermod::Error& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return layermod::ImporterExitCode(error);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", argc > 0 ? argv[argc - 1] : "mesh", error.what());
    return layermod::kImporterFormatError;
  }
}
