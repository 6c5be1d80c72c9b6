// SPDX-License-Identifier: MIT
// Small mesh files written by the tests themselves, in the text formats assimp reads.
#pragma once

#include <filesystem>
#include <string>

namespace layermod::test {

void WriteTextFile(const std::filesystem::path& path, const std::string& text);

// An axis-aligned cube [lo, lo + side]^3 as 8 vertices and 12 triangles.
std::string CubePly(double side, double lo = 0.0, bool with_colors = false);
std::string CubeObj(double side);
std::string CubeOff(double side);
// One facet per triangle: 36 corner vertices that must be merged to 8.
std::string CubeStl(double side);

// The cube's 8 "x y z" lines and 12 "3 a b c" lines, for hand-made PLY variants.
std::string CubeVertexLines(double side, double lo = 0.0);
std::string CubeFaceLines();

// A PLY with the given vertex lines ("x y z") and face lines ("3 a b c").
std::string PlainPly(const std::string& vertices, int vertex_count, const std::string& faces,
                     int face_count);

}  // namespace layermod::test
