// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/units.h"
#include "util/error.h"

namespace layermod {

// Triangles with merged vertices, in mm, before they become an OpenMesh mesh.
struct TriangleSoup {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::array<unsigned char, 3>> colors;  // one per position (grey when uncoloured)
  std::vector<std::array<int, 3>> triangles;         // zero-area triangles already dropped
  bool has_colors = false;
};

struct MeshImportOptions {
  LengthUnit units = LengthUnit::kMillimetre;
  std::size_t max_triangles = 20'000'000;
  // assimp runs in its own process (the layermod-import-mesh helper): a reader that crashes or
  // hangs on a hostile file becomes a FormatError instead of taking the caller down. Off for the
  // helper itself and for debugging the reader in-process.
  bool isolate = true;
  std::chrono::seconds timeout{300};
};

// The helper executable that imports in its own process, and how it is found: the environment
// variable, then beside the running executable, then in ../libexec/layermod/ from it (installed
// layout), then in the install prefix's and the Debian package's libexec/layermod/ (programs
// linking the installed library live elsewhere), then, in a CMake build tree, in its app/.
inline constexpr char kMeshImporterName[] = "layermod-import-mesh";
inline constexpr char kMeshImporterEnv[] = "LAYERMOD_MESH_IMPORTER";
std::filesystem::path MeshImporterPath();  // empty when not found

// Exit codes of the helper for each error type (1 is left to crashes reported by a sanitizer).
inline constexpr int kImporterFormatError = 2;
inline constexpr int kImporterIoError = 3;
inline constexpr int kImporterError = 4;
int ImporterExitCode(const Error& error);

// Reads any mesh assimp reads, with every node transform applied, vertices at equal positions
// merged, and converted to mm. Throws IoError/FormatError naming the file. When isolated but the
// helper is not found, logs a warning and reads in this process.
TriangleSoup ImportTriangles(const std::filesystem::path& path, const MeshImportOptions& options);

// The soup as bytes and back (how the child process hands it over). Parsing validates sizes
// and indices and throws FormatError naming `name`.
std::string SerializeSoup(const TriangleSoup& soup);
TriangleSoup ParseSoup(const std::string& bytes, const std::string& name);

}  // namespace layermod
