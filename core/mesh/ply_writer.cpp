// SPDX-License-Identifier: MIT
// SaveModelPly (declared in mesh/model.h): the project's own mesh output, e.g. the bundled sample.
#include <array>
#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/model.h"
#include "util/atomic_file.h"

namespace layermod {
namespace {

// Explicit byte order: the file is little-endian whatever the host.
void AppendU32(std::string& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>((value >> shift) & 0xff));
}

void AppendFloat(std::string& out, double value) {
  AppendU32(out, std::bit_cast<std::uint32_t>(static_cast<float>(value)));
}

std::string Header(std::size_t vertices, std::size_t faces) {
  std::ostringstream out;
  out << "ply\nformat binary_little_endian 1.0\ncomment LayerMOD model, millimetres\n"
      << "element vertex " << vertices << '\n';
  for (const char* name : {"x", "y", "z", "nx", "ny", "nz"})
    out << "property float " << name << '\n';
  for (const char* name : {"red", "green", "blue"}) out << "property uchar " << name << '\n';
  out << "element face " << faces << "\nproperty list uchar int vertex_indices\nend_header\n";
  return out.str();
}

}  // namespace

void SaveModelPly(const std::filesystem::path& path, const TriMesh& mesh) {
  // Deleted-but-not-collected elements are skipped, so indices are renumbered.
  std::vector<std::int64_t> index(mesh.n_vertices(), -1);
  std::size_t vertex_count = 0;
  for (const auto vh : mesh.vertices()) index[vh.idx()] = static_cast<std::int64_t>(vertex_count++);
  std::size_t face_count = 0;
  for ([[maybe_unused]] const auto fh : mesh.faces()) ++face_count;

  std::string bytes = Header(vertex_count, face_count);
  bytes.reserve(bytes.size() + vertex_count * 27 + face_count * 13);
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    const auto& n = mesh.normal(vh);
    const auto& c = mesh.color(vh);
    for (int k = 0; k < 3; ++k) AppendFloat(bytes, p[k]);
    for (int k = 0; k < 3; ++k) AppendFloat(bytes, n[k]);
    for (int k = 0; k < 3; ++k) bytes.push_back(static_cast<char>(c[k]));
  }
  for (const auto fh : mesh.faces()) {
    bytes.push_back(3);
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) {
      if (k++ < 3) AppendU32(bytes, static_cast<std::uint32_t>(index[vh.idx()]));
    }
  }
  WriteFileAtomically(path, bytes);
}

}  // namespace layermod
