// SPDX-License-Identifier: MIT
#pragma once

// The per-object mesh entries of a *.layermod archive (layout in docs/archive-format.md): the
// detector refines and verifies poses against the model, so the archive carries it.

#include <cstdint>
#include <string>
#include <string_view>

#include "mesh/render_mesh.h"

namespace layermod {

inline constexpr std::size_t kMeshVertexBytes = 24;    // position + colour, 6 x f32
inline constexpr std::size_t kMeshTriangleBytes = 12;  // 3 x u32

// Where an object's mesh lives in the container and how to check it.
struct MeshInfo {
  std::string entry;  // zip entry name
  std::uint64_t vertex_count = 0;
  std::uint64_t triangle_count = 0;
  std::uint64_t byte_size = 0;
  std::uint32_t crc32 = 0;

  bool operator==(const MeshInfo&) const = default;
};

std::string MeshEntryName(std::int32_t obj_id);

// Checks sizes, finite positions, colours in [0, 1] and triangle indices. Throws FormatError
// (no file name).
void ValidateMesh(const RenderMesh& mesh);

std::string EncodeMesh(const RenderMesh& mesh);
MeshInfo DescribeMesh(std::string entry, const RenderMesh& mesh, std::string_view bytes);

// Decodes and validates; `info` gives the counts, checked against the byte size first.
RenderMesh DecodeMesh(std::string_view bytes, const MeshInfo& info);

}  // namespace layermod
