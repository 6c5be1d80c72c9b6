// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <filesystem>

namespace layermod {

// Checks the header of a PLY file before assimp reads it: assimp's PLY reader loops forever on a
// header without `end_header` and allocates whatever element counts a header declares. Throws
// FormatError naming the file for a malformed header, unknown keywords or types, more faces than
// `max_triangles`, or (binary files) counts that need more bytes than the file has. A file named
// *.ply or starting with "ply" must have exactly "ply" as its first line (assimp takes either
// for PLY and loops forever on some near-misses); other files are left to their own readers.
void CheckPlyHeader(const std::filesystem::path& path, std::size_t max_triangles);

}  // namespace layermod
