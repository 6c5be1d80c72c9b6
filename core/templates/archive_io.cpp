// SPDX-License-Identifier: MIT
//
// The *.layermod file (full description: docs/archive-format.md).
//
// A ZIP container, so standard tools can list and unpack it, holding in this order:
//   mimetype       STORED, exactly "application/x-layermod": the magic; must be the first entry
//   manifest.json  readable JSON: format_version, tool_version, created_utc, endianness, camera,
//                  objects (ids, names, mesh file + hash, units, sphere, bbox, layer depths,
//                  training profile, mesh entry), counts, and for each binary table its entry
//                  name, record size and count, byte size and CRC-32 (zlib's)
//   templates.bin  deflated; one fixed-size little-endian record per template, in id order
//                  (everything of TemplateRecord but the features, plus each level's box and
//                  the offset/count of its features in features.bin)
//   features.bin   deflated; 6-byte little-endian features (x i16, y i16, label u8,
//                  modality u8), template after template, level after level
//   view_tree.bin  deflated; the view tree: one u32 per template, in id order, the id of its
//                  view cluster's representative or 0xFFFFFFFF (no cluster); since version 2
//   mesh_<id>.bin  deflated; each object's model (positions and colours as f32, triangles as
//                  u32), for pose refinement and verification
// Every number is written byte by byte (floats through their bit patterns), never by copying
// structs, so the file does not depend on the platform or compiler.
//
// Reading trusts nothing: the magic, the version (checked before any other field), every
// manifest field, table sizes against the record counts, the container's and the manifest's
// CRC-32, and every record value (ids, objects, layers, feature offsets and coordinates,
// labels, modalities, finite floats, orthonormal rotations, box sizes, statuses). Declared
// sizes are compared with the real data before anything is allocated from them. Any problem is
// a FormatError naming the file. Tables are inflated with libdeflate (zip_container.cpp): with
// libzip's own zlib streaming, loading 20k templates took about twice as long.

#include <nlohmann/json.hpp>

#include "templates/archive.h"
#include "templates/archive_manifest.h"
#include "templates/archive_meshes.h"
#include "templates/archive_tables.h"
#include "templates/byte_io.h"
#include "templates/zip_container.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

constexpr std::string_view kMimeType = "application/x-layermod";
constexpr std::string_view kZipSignature = "PK\x03\x04";
constexpr const char* kManifestEntry = "manifest.json";
constexpr std::uint64_t kMaxManifestBytes = 16ull << 20;

// Keeps messages readable when a foreign file puts binary junk where a name should be.
std::string Printable(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 64)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > 64) out += "...";
  return out;
}

// ---- writing ----

std::string EncodeViewLeaders(const std::vector<std::uint32_t>& leaders) {
  std::string bytes;
  bytes.reserve(leaders.size() * kViewLeaderRecordBytes);
  ByteWriter writer(bytes);
  for (std::uint32_t leader : leaders) writer.Put(leader);
  return bytes;
}

std::vector<MeshInfo> EncodeMeshes(const ArchiveManifest& manifest,
                                   std::vector<ZipEntry>& entries) {
  std::vector<MeshInfo> meshes;
  for (const ArchiveObject& object : manifest.objects) {
    std::string bytes = EncodeMesh(object.mesh);
    meshes.push_back(DescribeMesh(MeshEntryName(object.obj_id), object.mesh, bytes));
    entries.push_back({meshes.back().entry, std::move(bytes), true});
  }
  return meshes;
}

std::string EncodeArchive(const TemplateArchive& archive) {
  const ArchiveManifest& manifest = archive.manifest();
  ValidateManifest(manifest);
  const RecordValidator validator(manifest);
  for (std::size_t i = 0; i < archive.templates().size(); ++i) {
    validator.Check(archive.templates()[i], i);
  }
  EncodedTables tables = EncodeTables(archive.templates());
  const TableInfo template_table =
      DescribeTable("templates.bin", kTemplateRecordBytes, tables.templates);
  const TableInfo feature_table =
      DescribeTable("features.bin", kFeatureRecordBytes, tables.features);
  std::string view_tree_bin = EncodeViewLeaders(archive.ViewLeaders());
  const ViewTreeInfo view_tree = {
      DescribeTable("view_tree.bin", kViewLeaderRecordBytes, view_tree_bin), kViewClusterRadiusDeg,
      archive.ViewClusterCount()};
  std::vector<ZipEntry> mesh_entries;
  const std::vector<MeshInfo> meshes = EncodeMeshes(manifest, mesh_entries);
  const nlohmann::json manifest_json = ManifestToJson(manifest, archive.templates(), template_table,
                                                      feature_table, view_tree, meshes);
  std::vector<ZipEntry> entries;
  entries.push_back({"mimetype", std::string(kMimeType), /*compress=*/false});
  entries.push_back(
      {kManifestEntry,
       manifest_json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n", true});
  entries.push_back({template_table.entry, std::move(tables.templates), true});
  entries.push_back({feature_table.entry, std::move(tables.features), true});
  entries.push_back({view_tree.table.entry, std::move(view_tree_bin), true});
  for (ZipEntry& entry : mesh_entries) entries.push_back(std::move(entry));
  return WriteZip(entries);
}

// ---- reading ----

void CheckMimetype(const ZipReader& zip) {
  if (zip.EntryCount() == 0) throw FormatError("not a LayerMOD archive (empty zip file)");
  const ZipEntryInfo& first = zip.Entry(0);
  if (first.name != "mimetype") {
    throw FormatError("not a LayerMOD archive (first entry is '" + Printable(first.name) +
                      "', expected 'mimetype')");
  }
  if (!first.stored) throw FormatError("not a LayerMOD archive ('mimetype' is compressed)");
  const std::string content = zip.Read(0, kMimeType.size() + 64);
  if (content != kMimeType) {
    throw FormatError("not a LayerMOD archive (mimetype is '" + Printable(content) +
                      "', expected '" + std::string(kMimeType) + "')");
  }
}

ParsedManifest ReadManifest(const ZipReader& zip) {
  const auto index = zip.Find(kManifestEntry);
  if (!index) throw FormatError("'manifest.json' is missing");
  const std::string text = zip.Read(*index, kMaxManifestBytes);
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw FormatError("'manifest.json' is not valid JSON");
  ParsedManifest parsed = ManifestFromJson(json);
  ValidateManifest(parsed.manifest);
  return parsed;
}

std::string ReadTable(const ZipReader& zip, const TableInfo& table, std::uint64_t record_size) {
  const std::string name = "table '" + Printable(table.entry) + "'";
  if (table.record_size != record_size) {
    throw FormatError(name + " has records of " + std::to_string(table.record_size) +
                      " bytes, expected " + std::to_string(record_size));
  }
  if (table.byte_size % record_size != 0 || table.byte_size / record_size != table.record_count) {
    throw FormatError(name + ": " + std::to_string(table.record_count) + " records of " +
                      std::to_string(record_size) + " bytes do not make " +
                      std::to_string(table.byte_size) + " bytes");
  }
  const auto index = zip.Find(table.entry);
  if (!index) throw FormatError(name + " is missing from the container");
  const std::uint64_t stored_size = zip.Entry(*index).size;
  if (stored_size != table.byte_size) {
    throw FormatError(name + " holds " + std::to_string(stored_size) +
                      " bytes, the manifest says " + std::to_string(table.byte_size));
  }
  // The container checks the bytes against its own CRC-32 while reading them, so comparing the
  // manifest's value with that one spares a second pass over the data.
  if (zip.Entry(*index).crc32 != table.crc32) {
    throw FormatError(name + " is damaged (CRC-32 mismatch with the manifest)");
  }
  return zip.Read(*index, table.byte_size);
}

RenderMesh ReadMesh(const ZipReader& zip, const MeshInfo& mesh) {
  const std::string name = "mesh '" + Printable(mesh.entry) + "'";
  const auto index = zip.Find(mesh.entry);
  if (!index) throw FormatError(name + " is missing from the container");
  if (zip.Entry(*index).size != mesh.byte_size) {
    throw FormatError(name + " holds " + std::to_string(zip.Entry(*index).size) +
                      " bytes, the manifest says " + std::to_string(mesh.byte_size));
  }
  if (zip.Entry(*index).crc32 != mesh.crc32) {
    throw FormatError(name + " is damaged (CRC-32 mismatch with the manifest)");
  }
  return DecodeMesh(zip.Read(*index, mesh.byte_size), mesh);
}

std::vector<std::uint32_t> DecodeViewLeaders(std::string_view bytes) {
  std::vector<std::uint32_t> leaders(bytes.size() / kViewLeaderRecordBytes);
  ByteReader reader(bytes);
  for (std::uint32_t& leader : leaders) leader = reader.Get<std::uint32_t>();
  return leaders;
}

TemplateArchive DecodeArchive(std::string_view bytes) {
  if (bytes.empty()) throw FormatError("empty file, not a LayerMOD archive");
  if (!bytes.starts_with(kZipSignature)) {
    throw FormatError("not a LayerMOD archive (no zip signature)");
  }
  const ZipReader zip(bytes);
  CheckMimetype(zip);
  ParsedManifest parsed = ReadManifest(zip);
  if (parsed.template_table.entry == parsed.feature_table.entry ||
      (parsed.view_tree && (parsed.view_tree->table.entry == parsed.template_table.entry ||
                            parsed.view_tree->table.entry == parsed.feature_table.entry))) {
    throw FormatError("two tables share one entry");
  }
  std::vector<TemplateRecord> templates;
  {
    const std::string templates_bin = ReadTable(zip, parsed.template_table, kTemplateRecordBytes);
    const std::string features_bin = ReadTable(zip, parsed.feature_table, kFeatureRecordBytes);
    templates = DecodeTables(templates_bin, features_bin, parsed.manifest);
  }
  for (std::size_t i = 0; i < parsed.meshes.size(); ++i) {
    parsed.manifest.objects[i].mesh = ReadMesh(zip, parsed.meshes[i]);
  }
  if (parsed.counts != CountsJson(parsed.manifest, templates)) {
    throw FormatError("manifest counts do not match the template table");
  }
  if (!parsed.view_tree) {
    // Version 1: no stored tree, so it is built now, as training builds it.
    return TemplateArchive(std::move(parsed.manifest), std::move(templates));
  }
  const ViewTreeInfo& view_tree = *parsed.view_tree;
  const std::vector<std::uint32_t> leaders =
      DecodeViewLeaders(ReadTable(zip, view_tree.table, kViewLeaderRecordBytes));
  TemplateArchive archive(std::move(parsed.manifest), std::move(templates), leaders,
                          view_tree.radius_deg);
  if (archive.ViewClusterCount() != view_tree.clusters) {
    throw FormatError("view tree: the manifest counts " + std::to_string(view_tree.clusters) +
                      " clusters, the table holds " + std::to_string(archive.ViewClusterCount()));
  }
  return archive;
}

}  // namespace

void WriteArchive(const std::filesystem::path& path, const TemplateArchive& archive) {
  CheckWritableTarget(path);  // fail before the encoding work
  std::string bytes;
  try {
    bytes = EncodeArchive(archive);
  } catch (const Error& error) {
    throw Error(Quoted(path) + ": archive not written: " + error.what());
  }
  WriteFileAtomically(path, bytes);
}

TemplateArchive ReadArchive(const std::filesystem::path& path) {
  const std::string bytes = ReadFileBytes(path);
  return ReadArchiveBytes(bytes, path.string());
}

TemplateArchive ReadArchiveBytes(std::string_view bytes, const std::string& name) {
  try {
    return DecodeArchive(bytes);
  } catch (const Error& error) {
    throw FormatError("'" + name + "': " + error.what());
  } catch (const nlohmann::json::exception& error) {
    throw FormatError("'" + name + "': manifest: " + error.what());
  }
}

}  // namespace layermod
