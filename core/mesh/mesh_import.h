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
  // assimp runs in a child process: a reader that crashes or hangs on a hostile file becomes a
  // FormatError instead of taking the caller down. Off only for debugging the reader in-process.
  bool isolate = true;
  std::chrono::seconds timeout{300};
};

// Reads any mesh assimp reads, with every node transform applied, vertices at equal positions
// merged, and converted to mm. Throws IoError/FormatError naming the file.
TriangleSoup ImportTriangles(const std::filesystem::path& path, const MeshImportOptions& options);

// The soup as bytes and back (how the child process hands it over). Parsing validates sizes
// and indices and throws FormatError naming `name`.
std::string SerializeSoup(const TriangleSoup& soup);
TriangleSoup ParseSoup(const std::string& bytes, const std::string& name);

}  // namespace layermod
