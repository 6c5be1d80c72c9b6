// SPDX-License-Identifier: MIT
#include "templates/archive_meshes.h"

#include <cmath>

#include "templates/archive_manifest.h"
#include "templates/byte_io.h"
#include "util/error.h"

namespace layermod {
namespace {

bool IsUnitColour(const Eigen::Vector3f& colour) {
  return colour.allFinite() && (colour.array() >= 0.0f).all() && (colour.array() <= 1.0f).all();
}

}  // namespace

std::string MeshEntryName(std::int32_t obj_id) { return "mesh_" + std::to_string(obj_id) + ".bin"; }

void ValidateMesh(const RenderMesh& mesh) {
  if (mesh.colors.size() != mesh.positions.size()) {
    throw FormatError("mesh has " + std::to_string(mesh.colors.size()) + " colours for " +
                      std::to_string(mesh.positions.size()) + " vertices");
  }
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!mesh.positions[i].allFinite()) {
      throw FormatError("mesh vertex " + std::to_string(i) + " is not finite");
    }
    if (!IsUnitColour(mesh.colors[i])) {
      throw FormatError("mesh vertex " + std::to_string(i) + " has a colour outside 0..1");
    }
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t vertex : mesh.triangles[t]) {
      if (vertex >= mesh.positions.size()) {
        throw FormatError("mesh triangle " + std::to_string(t) + " uses vertex " +
                          std::to_string(vertex) + " of " + std::to_string(mesh.positions.size()));
      }
    }
  }
}

std::string EncodeMesh(const RenderMesh& mesh) {
  std::string bytes;
  bytes.reserve(mesh.positions.size() * kMeshVertexBytes +
                mesh.triangles.size() * kMeshTriangleBytes);
  ByteWriter out(bytes);
  for (const Eigen::Vector3f& position : mesh.positions) {
    for (int i = 0; i < 3; ++i) out.Put(position(i));
  }
  for (const Eigen::Vector3f& colour : mesh.colors) {
    for (int i = 0; i < 3; ++i) out.Put(colour(i));
  }
  for (const auto& triangle : mesh.triangles) {
    for (std::uint32_t vertex : triangle) out.Put(vertex);
  }
  return bytes;
}

MeshInfo DescribeMesh(std::string entry, const RenderMesh& mesh, std::string_view bytes) {
  return {std::move(entry), mesh.positions.size(), mesh.triangles.size(), bytes.size(),
          Crc32(bytes)};
}

RenderMesh DecodeMesh(std::string_view bytes, const MeshInfo& info) {
  // Counts are checked against the real size before they size any allocation.
  const bool fits =
      info.vertex_count <= bytes.size() / kMeshVertexBytes &&
      info.triangle_count <= bytes.size() / kMeshTriangleBytes &&
      info.vertex_count * kMeshVertexBytes + info.triangle_count * kMeshTriangleBytes ==
          bytes.size();
  if (!fits) {
    throw FormatError("'" + info.entry + "': " + std::to_string(info.vertex_count) +
                      " vertices and " + std::to_string(info.triangle_count) +
                      " triangles do not make " + std::to_string(bytes.size()) + " bytes");
  }
  RenderMesh mesh;
  mesh.positions.resize(info.vertex_count);
  mesh.colors.resize(info.vertex_count);
  mesh.triangles.resize(info.triangle_count);
  ByteReader in(bytes);
  for (Eigen::Vector3f& position : mesh.positions) {
    for (int i = 0; i < 3; ++i) position(i) = in.Get<float>();
  }
  for (Eigen::Vector3f& colour : mesh.colors) {
    for (int i = 0; i < 3; ++i) colour(i) = in.Get<float>();
  }
  for (auto& triangle : mesh.triangles) {
    for (std::uint32_t& vertex : triangle) vertex = in.Get<std::uint32_t>();
  }
  try {
    ValidateMesh(mesh);
  } catch (const FormatError& error) {
    throw FormatError("'" + info.entry + "': " + error.what());
  }
  return mesh;
}

}  // namespace layermod
