// SPDX-License-Identifier: MIT
#include "mesh_files.h"

#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace layermod::test {
namespace {

// Corner i of the cube has x = bit 0, y = bit 1, z = bit 2.
std::array<std::array<double, 3>, 8> Corners(double side, double lo) {
  std::array<std::array<double, 3>, 8> corners{};
  for (int i = 0; i < 8; ++i) {
    corners[i] = {lo + (i & 1 ? side : 0.0), lo + (i & 2 ? side : 0.0), lo + (i & 4 ? side : 0.0)};
  }
  return corners;
}

// Outward-facing triangles (counter-clockwise seen from outside).
constexpr std::array<std::array<int, 3>, 12> kCubeTriangles = {{
    {0, 2, 3},
    {0, 3, 1},  // z = lo
    {4, 5, 7},
    {4, 7, 6},  // z = hi
    {0, 1, 5},
    {0, 5, 4},  // y = lo
    {2, 6, 7},
    {2, 7, 3},  // y = hi
    {0, 4, 6},
    {0, 6, 2},  // x = lo
    {1, 3, 7},
    {1, 7, 5},  // x = hi
}};

}  // namespace

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write test file " + path.string());
}

std::string PlainPly(const std::string& vertices, int vertex_count, const std::string& faces,
                     int face_count) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\nelement vertex " << vertex_count
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << face_count
      << "\nproperty list uchar int vertex_indices\nend_header\n"
      << vertices << faces;
  return out.str();
}

std::string CubeVertexLines(double side, double lo) {
  std::ostringstream out;
  for (const auto& c : Corners(side, lo)) out << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  return out.str();
}

std::string CubeFaceLines() {
  std::ostringstream out;
  for (const auto& t : kCubeTriangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  return out.str();
}

std::string CubePly(double side, double lo, bool with_colors) {
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\nelement vertex 8\n"
      << "property float x\nproperty float y\nproperty float z\n";
  if (with_colors) out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out << "element face 12\nproperty list uchar int vertex_indices\nend_header\n";
  const auto corners = Corners(side, lo);
  for (int i = 0; i < 8; ++i) {
    out << corners[i][0] << ' ' << corners[i][1] << ' ' << corners[i][2];
    if (with_colors) out << ' ' << 30 * i << ' ' << 255 - 10 * i << ' ' << 7;
    out << '\n';
  }
  out << CubeFaceLines();
  return out.str();
}

std::string CubeObj(double side) {
  std::ostringstream out;
  out << "# cube\no cube\n";
  for (const auto& c : Corners(side, 0.0))
    out << "v " << c[0] << ' ' << c[1] << ' ' << c[2] << '\n';
  // Quads: the loader must triangulate them.
  for (int t = 0; t < 12; t += 2) {
    const auto& a = kCubeTriangles[t];
    const auto& b = kCubeTriangles[t + 1];
    out << "f " << a[0] + 1 << ' ' << a[1] + 1 << ' ' << a[2] + 1 << ' ' << b[2] + 1 << '\n';
  }
  return out.str();
}

std::string CubeOff(double side) {
  std::ostringstream out;
  out << "OFF\n8 12 0\n" << CubeVertexLines(side) << CubeFaceLines();
  return out.str();
}

std::string CubeStl(double side) {
  std::ostringstream out;
  out << "solid cube\n";
  const auto corners = Corners(side, 0.0);
  for (const auto& t : kCubeTriangles) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (int k : t)
      out << "vertex " << corners[k][0] << ' ' << corners[k][1] << ' ' << corners[k][2] << '\n';
    out << "endloop\nendfacet\n";
  }
  out << "endsolid cube\n";
  return out.str();
}

}  // namespace layermod::test
