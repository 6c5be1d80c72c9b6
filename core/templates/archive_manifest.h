// SPDX-License-Identifier: MIT
#pragma once

// The readable manifest.json of a *.layermod archive (fields in docs/archive-format.md).
// Internal to the archive reader/writer; tests use it to build corrupt archives.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "templates/archive.h"
#include "templates/archive_meshes.h"

namespace layermod {

// Where a binary table lives in the container and how to check it.
struct TableInfo {
  std::string entry;  // zip entry name
  std::uint64_t record_size = 0;
  std::uint64_t record_count = 0;
  std::uint64_t byte_size = 0;
  std::uint32_t crc32 = 0;  // CRC-32 (zlib's and ZIP's) of the uncompressed bytes

  bool operator==(const TableInfo&) const = default;
};

// The view tree's table (one leader per template, templates/view_clusters.h) and the radius its
// clusters were built with.
inline constexpr std::size_t kViewLeaderRecordBytes = 4;
struct ViewTreeInfo {
  TableInfo table;
  double radius_deg = 0.0;
  std::uint64_t clusters = 0;

  bool operator==(const ViewTreeInfo&) const = default;
};

TableInfo DescribeTable(std::string entry, std::uint64_t record_size, std::string_view bytes);
std::uint32_t Crc32(std::string_view bytes);

// Statistics the manifest carries for readers ("layermod inspect"); checked on load.
nlohmann::json CountsJson(const ArchiveManifest& manifest,
                          std::span<const TemplateRecord> templates);

// `meshes` describes the mesh entry of each object, in the order of manifest.objects.
nlohmann::json ManifestToJson(const ArchiveManifest& manifest,
                              std::span<const TemplateRecord> templates,
                              const TableInfo& template_table, const TableInfo& feature_table,
                              const ViewTreeInfo& view_tree, std::span<const MeshInfo> meshes);

struct ParsedManifest {
  ArchiveManifest manifest;  // objects without their meshes (those are in separate entries)
  int format_version = kArchiveFormatVersion;
  TableInfo template_table;
  TableInfo feature_table;
  std::optional<ViewTreeInfo> view_tree;  // absent in version 1
  std::vector<MeshInfo> meshes;           // one per object
  nlohmann::json counts;
};

// Checks the format version first (kOldestArchiveFormatVersion..kArchiveFormatVersion), then
// every field. Throws FormatError naming the field
// (no file name).
ParsedManifest ManifestFromJson(const nlohmann::json& json);

// Checks the values of a manifest (camera, objects and their meshes) before writing or after
// reading.
// Throws FormatError naming the object and the problem.
void ValidateManifest(const ArchiveManifest& manifest);

}  // namespace layermod
