// SPDX-License-Identifier: MIT
#include "templates/archive_manifest.h"

#include <libdeflate.h>

#include <cmath>
#include <limits>
#include <set>

#include "geometry/units.h"
#include "templates/json_fields.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr const char* kWhat = "manifest";
constexpr std::size_t kMaxLayers = 65536;  // layer_index is 16-bit in the template table

nlohmann::json VectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json MeshJson(const MeshInfo& mesh) {
  return {{"entry", mesh.entry},
          {"vertex_count", mesh.vertex_count},
          {"triangle_count", mesh.triangle_count},
          {"byte_size", mesh.byte_size},
          {"crc32", mesh.crc32}};
}

nlohmann::json ObjectJson(const ArchiveObject& object, const MeshInfo& mesh) {
  return {
      {"obj_id", object.obj_id},
      {"name", object.name},
      {"mesh_file", object.mesh_file},
      {"mesh_hash", object.mesh_hash},
      {"units", object.units},
      {"sphere",
       {{"centre_mm", VectorJson(object.sphere.centre)}, {"radius_mm", object.sphere.radius_mm}}},
      {"diameter_mm", object.diameter_mm},
      {"bbox_min_mm", VectorJson(object.bbox_min)},
      {"bbox_size_mm", VectorJson(object.bbox_size)},
      {"layer_depths_mm", object.layer_depths_mm},
      {"profile", ToJson(object.profile)},
      {"mesh", MeshJson(mesh)}};
}

nlohmann::json TableJson(const TableInfo& table) {
  return {{"entry", table.entry},
          {"record_size", table.record_size},
          {"record_count", table.record_count},
          {"byte_size", table.byte_size},
          {"crc32", table.crc32}};
}

Eigen::Vector3d ReadVector(const JsonFields& fields, std::string_view key) {
  const nlohmann::json& array = fields.Array(key);
  if (array.size() != 3) fields.Fail(key, "must hold 3 numbers");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    if (!array[i].is_number()) fields.Fail(key, "must hold 3 numbers");
    v(i) = array[i].get<double>();
  }
  return v;
}

PinholeCamera ReadCamera(const JsonFields& fields) {
  PinholeCamera camera;
  camera.fx = fields.Number("fx");
  camera.fy = fields.Number("fy");
  camera.cx = fields.Number("cx");
  camera.cy = fields.Number("cy");
  camera.width = static_cast<int>(fields.Integer("width", 1, 16384));
  camera.height = static_cast<int>(fields.Integer("height", 1, 16384));
  return camera;
}

std::vector<double> ReadLayers(const JsonFields& fields) {
  const nlohmann::json& array = fields.Array("layer_depths_mm");
  if (array.size() > kMaxLayers) fields.Fail("layer_depths_mm", "holds too many layers");
  std::vector<double> layers;
  for (const nlohmann::json& value : array) {
    if (!value.is_number()) fields.Fail("layer_depths_mm", "must hold numbers");
    layers.push_back(value.get<double>());
  }
  return layers;
}

MeshInfo ReadMeshInfo(const JsonFields& fields) {
  MeshInfo mesh;
  mesh.entry = fields.String("entry");
  mesh.vertex_count = fields.Unsigned("vertex_count");
  mesh.triangle_count = fields.Unsigned("triangle_count");
  mesh.byte_size = fields.Unsigned("byte_size");
  mesh.crc32 = static_cast<std::uint32_t>(fields.Integer("crc32", 0, 0xFFFFFFFFll));
  return mesh;
}

ArchiveObject ReadObject(const JsonFields& fields) {
  ArchiveObject object;
  object.obj_id =
      static_cast<std::int32_t>(fields.Integer("obj_id", std::numeric_limits<std::int32_t>::min(),
                                               std::numeric_limits<std::int32_t>::max()));
  object.name = fields.String("name");
  object.mesh_file = fields.String("mesh_file");
  object.mesh_hash = fields.String("mesh_hash");
  object.units = fields.String("units");
  const JsonFields sphere = fields.Object("sphere");
  object.sphere.centre = ReadVector(sphere, "centre_mm");
  object.sphere.radius_mm = sphere.Number("radius_mm");
  object.diameter_mm = fields.Number("diameter_mm");
  object.bbox_min = ReadVector(fields, "bbox_min_mm");
  object.bbox_size = ReadVector(fields, "bbox_size_mm");
  object.layer_depths_mm = ReadLayers(fields);
  try {
    object.profile = TrainingProfileFromJson(fields.Get("profile"));
  } catch (const FormatError& error) {
    fields.Fail("profile", std::string("is invalid: ") + error.what());
  }
  return object;
}

TableInfo ReadTable(const JsonFields& fields) {
  TableInfo table;
  table.entry = fields.String("entry");
  table.record_size = fields.Unsigned("record_size");
  table.record_count = fields.Unsigned("record_count");
  table.byte_size = fields.Unsigned("byte_size");
  table.crc32 = static_cast<std::uint32_t>(fields.Integer("crc32", 0, 0xFFFFFFFFll));
  return table;
}

ViewTreeInfo ReadViewTree(const JsonFields& fields, const JsonFields& tables) {
  ViewTreeInfo view_tree;
  const JsonFields tree = fields.Object("view_tree");
  view_tree.radius_deg = tree.Number("radius_deg");
  if (!(view_tree.radius_deg > 0.0 && view_tree.radius_deg <= 180.0)) {
    tree.Fail("radius_deg", "must lie in (0, 180]");
  }
  view_tree.clusters = tree.Unsigned("clusters");
  view_tree.table = ReadTable(tables.Object("view_tree"));
  return view_tree;
}

void ValidateObject(const ArchiveObject& object) {
  const std::string what = "object " + std::to_string(object.obj_id) + ": ";
  try {
    ParseLengthUnit(object.units);
    object.profile.Validate();
    ValidateMesh(object.mesh);
  } catch (const Error& error) {
    throw FormatError(what + error.what());
  }
  const Sphere& sphere = object.sphere;
  if (!sphere.centre.allFinite() || !std::isfinite(sphere.radius_mm) || sphere.radius_mm < 0.0) {
    throw FormatError(what + "sphere must be finite with a non-negative radius");
  }
  if (!std::isfinite(object.diameter_mm) || object.diameter_mm < 0.0) {
    throw FormatError(what + "diameter must be a non-negative number");
  }
  if (!object.bbox_min.allFinite() || !object.bbox_size.allFinite() ||
      (object.bbox_size.array() < 0.0).any()) {
    throw FormatError(what + "bounding box must be finite with a non-negative size");
  }
  if (object.layer_depths_mm.size() > kMaxLayers) throw FormatError(what + "too many layers");
  for (double depth_mm : object.layer_depths_mm) {
    if (!std::isfinite(depth_mm) || depth_mm <= 0.0) {
      throw FormatError(what + "layer depths must be positive numbers");
    }
  }
}

}  // namespace

std::uint32_t Crc32(std::string_view bytes) {
  return static_cast<std::uint32_t>(libdeflate_crc32(0, bytes.data(), bytes.size()));
}

TableInfo DescribeTable(std::string entry, std::uint64_t record_size, std::string_view bytes) {
  return {std::move(entry), record_size, record_size == 0 ? 0 : bytes.size() / record_size,
          bytes.size(), Crc32(bytes)};
}

nlohmann::json CountsJson(const ArchiveManifest& manifest,
                          std::span<const TemplateRecord> templates) {
  std::uint64_t weak = 0;
  std::uint64_t features = 0;
  nlohmann::json objects = nlohmann::json::array();
  for (const ArchiveObject& object : manifest.objects) {
    std::vector<std::uint64_t> per_layer(object.layer_depths_mm.size(), 0);
    std::uint64_t object_templates = 0;
    std::uint64_t object_weak = 0;
    for (const TemplateRecord& record : templates) {
      if (record.obj_id != object.obj_id) continue;
      ++object_templates;
      if (record.status != TemplateStatus::kOk) ++object_weak;
      if (record.layer_index < per_layer.size()) ++per_layer[record.layer_index];
    }
    objects.push_back({{"obj_id", object.obj_id},
                       {"templates", object_templates},
                       {"weak_templates", object_weak},
                       {"per_layer", per_layer}});
  }
  for (const TemplateRecord& record : templates) {
    if (record.status != TemplateStatus::kOk) ++weak;
    for (const TemplateLevel& level : record.levels) features += level.features.size();
  }
  return {{"templates", templates.size()},
          {"weak_templates", weak},
          {"features", features},
          {"objects", objects}};
}

nlohmann::json ManifestToJson(const ArchiveManifest& manifest,
                              std::span<const TemplateRecord> templates,
                              const TableInfo& template_table, const TableInfo& feature_table,
                              const ViewTreeInfo& view_tree, std::span<const MeshInfo> meshes) {
  if (meshes.size() != manifest.objects.size()) throw Error("one mesh per object expected");
  nlohmann::json objects = nlohmann::json::array();
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    objects.push_back(ObjectJson(manifest.objects[i], meshes[i]));
  }
  return {{"format_version", kArchiveFormatVersion},
          {"tool_version", manifest.tool_version},
          {"created_utc", manifest.created_utc},
          {"endianness", "little"},
          {"camera", CameraJson(manifest.camera)},
          {"objects", objects},
          {"counts", CountsJson(manifest, templates)},
          {"view_tree", {{"radius_deg", view_tree.radius_deg}, {"clusters", view_tree.clusters}}},
          {"tables",
           {{"templates", TableJson(template_table)},
            {"features", TableJson(feature_table)},
            {"view_tree", TableJson(view_tree.table)}}}};
}

ParsedManifest ManifestFromJson(const nlohmann::json& json) {
  const JsonFields fields(json, kWhat, "");
  // The version decides how to read the rest, so it is checked before anything else.
  const nlohmann::json& version = fields.Get("format_version");
  if (!version.is_number_integer()) fields.Fail("format_version", "must be an integer");
  if (version < kOldestArchiveFormatVersion || version > kArchiveFormatVersion) {
    throw FormatError("format version " + version.dump() + ", this tool reads " +
                      std::to_string(kOldestArchiveFormatVersion) + " to " +
                      std::to_string(kArchiveFormatVersion));
  }
  if (fields.String("endianness") != "little") {
    fields.Fail("endianness", "must be \"little\"");
  }
  ParsedManifest parsed;
  parsed.format_version = version.get<int>();
  parsed.manifest.format_version = parsed.format_version;
  parsed.manifest.tool_version = fields.String("tool_version");
  parsed.manifest.created_utc = fields.String("created_utc");
  parsed.manifest.camera = ReadCamera(fields.Object("camera"));
  const nlohmann::json& objects = fields.Array("objects");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const JsonFields object(objects[i], kWhat, "objects[" + std::to_string(i) + "]");
    parsed.manifest.objects.push_back(ReadObject(object));
    parsed.meshes.push_back(ReadMeshInfo(object.Object("mesh")));
    // Before format 3 depth normals were quantized in the camera frame, and profiles did not say.
    if (parsed.format_version < 3) {
      parsed.manifest.objects.back().profile.features.normal_frame = NormalFrame::kCamera;
    }
  }
  const JsonFields tables = fields.Object("tables");
  parsed.template_table = ReadTable(tables.Object("templates"));
  parsed.feature_table = ReadTable(tables.Object("features"));
  if (parsed.format_version >= 2) parsed.view_tree = ReadViewTree(fields, tables);
  fields.Object("counts");  // must be an object; compared with the tables by the reader
  parsed.counts = fields.Get("counts");
  return parsed;
}

void ValidateManifest(const ArchiveManifest& manifest) {
  try {
    manifest.camera.Validate();
  } catch (const Error& error) {
    throw FormatError(error.what());
  }
  std::set<std::int32_t> ids;
  for (const ArchiveObject& object : manifest.objects) {
    if (!ids.insert(object.obj_id).second) {
      throw FormatError("object id " + std::to_string(object.obj_id) + " appears twice");
    }
    ValidateObject(object);
  }
}

}  // namespace layermod
