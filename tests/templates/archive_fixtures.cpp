// SPDX-License-Identifier: MIT
#include "archive_fixtures.h"

#include <gtest/gtest.h>

#include <random>

#include "templates/archive_manifest.h"
#include "templates/archive_meshes.h"
#include "templates/archive_tables.h"
#include "templates/zip_container.h"
#include "util/error.h"

namespace layermod::test {
namespace {

TrainingProfile MakeProfile(int index) {
  TrainingProfile profile;
  profile.depth_min_mm = 550.5 + index;
  profile.depth_max_mm = 1234.25;
  profile.views.roll = {-30.0, 7.5, 30.0};
  profile.views.even_spacing_deg = 10.0 + index;
  profile.features.color_features = 80;
  profile.features.normal_features = 70;
  profile.features.weak_gradient = 12.3f;
  profile.features.depth_edge_fraction = 0.3f;
  profile.features.spread_px = {4, 7};
  return profile;
}

// A coloured box, half-size `half_mm`, 8 vertices and 12 triangles.
RenderMesh MakeBoxMesh(float half_mm) {
  RenderMesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.emplace_back(i & 1 ? half_mm : -half_mm, i & 2 ? half_mm : -half_mm,
                                i & 4 ? half_mm : -half_mm);
    mesh.colors.emplace_back(0.125f * i, 1.0f - 0.125f * i, 0.3f);
  }
  mesh.triangles = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                    {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
  return mesh;
}

ArchiveObject MakeObject(std::int32_t obj_id, int layers, int index) {
  ArchiveObject object;
  object.obj_id = obj_id;
  object.name = "part-" + std::to_string(obj_id) + " \xc3\xa4";  // UTF-8 survives
  object.mesh_file = "obj_" + std::to_string(obj_id) + ".ply";
  object.mesh_hash =
      "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a0" + std::to_string(index);
  object.units = index % 2 == 0 ? "mm" : "m";
  object.sphere.centre = Eigen::Vector3d(1.5, -2.25, 3.125 + index);
  object.sphere.radius_mm = 51.7 + index;
  object.diameter_mm = 2.0 * object.sphere.radius_mm;
  object.bbox_min = Eigen::Vector3d(-40.0, -30.5, -20.25);
  object.bbox_size = Eigen::Vector3d(80.0, 61.0, 40.5);
  for (int layer = 0; layer < layers; ++layer)
    object.layer_depths_mm.push_back(600.1 + 103.4 * layer);
  object.profile = MakeProfile(index);
  object.mesh = MakeBoxMesh(40.0f + 0.5f * static_cast<float>(index));
  return object;
}

TemplateLevel MakeLevel(int k, cv::Size box, int color, int normal, std::mt19937& rng) {
  TemplateLevel level;
  level.pyramid_level = k;
  level.width = box.width >> k;
  level.height = box.height >> k;
  std::uniform_int_distribution<int> x(0, level.width - 1), y(0, level.height - 1), label(0, 7);
  for (int i = 0; i < color + normal; ++i) {
    level.features.push_back({static_cast<std::int16_t>(x(rng)), static_cast<std::int16_t>(y(rng)),
                              static_cast<std::uint8_t>(label(rng)),
                              i < color ? Modality::kColorGradient : Modality::kDepthNormal});
  }
  return level;
}

TemplateRecord MakeRecord(std::uint32_t id, const ArchiveObject& object, int layer,
                          const SyntheticArchiveOptions& options, std::mt19937& rng) {
  std::uniform_real_distribution<double> azimuth(0.0, 360.0), elevation(0.0, 90.0),
      roll(-45.0, 45.0);
  std::uniform_int_distribution<int> position(0, 400), size(60, 160);
  TemplateRecord record;
  record.id = id;
  record.obj_id = object.obj_id;
  record.layer_index = static_cast<std::uint16_t>(layer);
  record.layer_depth_mm = static_cast<float>(object.layer_depths_mm[layer]);
  record.view = {azimuth(rng), elevation(rng), roll(rng)};
  record.cam_from_model =
      CamFromModelForView(record.view, object.sphere.centre, object.layer_depths_mm[layer]);
  record.bbox_px = cv::Rect(position(rng), position(rng), size(rng), size(rng));
  record.centre_offset_px = {record.bbox_px.width / 2.0f + 0.25f,
                             record.bbox_px.height / 2.0f - 0.75f};
  record.centre_minus_surface_mm = 12.5f + static_cast<float>(id) * 0.125f;
  record.depth_edge_count = 100 + static_cast<int>(id);
  const bool weak = options.weak_every > 0 && id % options.weak_every == 1;
  record.status = weak ? TemplateStatus::kTooFewFeatures : TemplateStatus::kOk;
  for (int k = 0; k < options.levels; ++k) {
    const int shift = options.halve_features_per_level ? k : 0;
    const int color = weak ? 3 : options.color_features >> shift;
    const int normal = weak ? 2 : options.normal_features >> shift;
    record.levels.push_back(MakeLevel(k, record.bbox_px.size(), color, normal, rng));
  }
  return record;
}

}  // namespace

TemplateArchive MakeSyntheticArchive(const SyntheticArchiveOptions& options) {
  std::mt19937 rng(options.seed);
  ArchiveManifest manifest;
  manifest.tool_version = "0.1.0-test";
  manifest.created_utc = "2024-05-01T12:34:56Z";
  manifest.camera = {572.4114, 573.57043, 325.2611, 242.04899, 640, 480};
  std::vector<TemplateRecord> templates;
  for (std::size_t i = 0; i < options.obj_ids.size(); ++i) {
    const int layers = options.layers_per_object.at(i);
    manifest.objects.push_back(MakeObject(options.obj_ids[i], layers, static_cast<int>(i)));
    for (int layer = 0; layer < layers; ++layer) {
      for (int v = 0; v < options.views_per_layer; ++v) {
        templates.push_back(MakeRecord(static_cast<std::uint32_t>(templates.size()),
                                       manifest.objects.back(), layer, options, rng));
      }
    }
  }
  return TemplateArchive(std::move(manifest), std::move(templates));
}

TemplateArchive MakeSmallArchive() {
  SyntheticArchiveOptions options;
  options.obj_ids = {1};
  options.layers_per_object = {1};
  options.views_per_layer = 3;
  options.color_features = 6;
  options.normal_features = 5;
  options.weak_every = 2;
  return MakeSyntheticArchive(options);
}

std::string PackUnchecked(const ArchiveManifest& manifest,
                          const std::vector<TemplateRecord>& templates) {
  EncodedTables tables = EncodeTables(templates);
  const TableInfo template_table =
      DescribeTable("templates.bin", kTemplateRecordBytes, tables.templates);
  const TableInfo feature_table =
      DescribeTable("features.bin", kFeatureRecordBytes, tables.features);
  // No layer is clustered: one "no cluster" leader per template.
  std::string view_tree_bin(templates.size() * kViewLeaderRecordBytes, '\xff');
  const ViewTreeInfo view_tree = {
      DescribeTable("view_tree.bin", kViewLeaderRecordBytes, view_tree_bin), 20.0, 0};
  std::vector<MeshInfo> meshes;
  std::vector<ZipEntry> entries = {{"mimetype", "application/x-layermod", false},
                                   {"manifest.json", "", true},
                                   {"templates.bin", std::move(tables.templates), true},
                                   {"features.bin", std::move(tables.features), true},
                                   {"view_tree.bin", std::move(view_tree_bin), true}};
  for (const ArchiveObject& object : manifest.objects) {
    std::string bytes = EncodeMesh(object.mesh);
    meshes.push_back(DescribeMesh(MeshEntryName(object.obj_id), object.mesh, bytes));
    entries.push_back({meshes.back().entry, std::move(bytes), true});
  }
  entries[1].data =
      ManifestToJson(manifest, templates, template_table, feature_table, view_tree, meshes).dump(2);
  return WriteZip(entries);
}

UnpackedArchive Unpack(std::string_view bytes) {
  const ZipReader zip(bytes);
  UnpackedArchive archive;
  archive.manifest = nlohmann::json::parse(zip.Read(zip.Find("manifest.json").value(), 1 << 24));
  archive.templates_bin = zip.Read(zip.Find("templates.bin").value(), 1ull << 32);
  archive.features_bin = zip.Read(zip.Find("features.bin").value(), 1ull << 32);
  if (const auto tree = zip.Find("view_tree.bin"))
    archive.view_tree_bin = zip.Read(*tree, 1ull << 32);
  for (std::size_t i = 0; i < zip.EntryCount(); ++i) {
    const std::string& name = zip.Entry(i).name;
    if (name == "mimetype" || name == "manifest.json" || name == "templates.bin" ||
        name == "features.bin" || name == "view_tree.bin") {
      continue;
    }
    archive.others.push_back({name, zip.Read(i, 1ull << 32), true});
  }
  return archive;
}

std::string Repack(UnpackedArchive archive, bool fix_tables) {
  if (fix_tables) {
    const auto describe = [&](const char* key, const TableInfo& table) {
      archive.manifest["tables"][key] = {{"entry", table.entry},
                                         {"record_size", table.record_size},
                                         {"record_count", table.record_count},
                                         {"byte_size", table.byte_size},
                                         {"crc32", table.crc32}};
    };
    describe("templates",
             DescribeTable("templates.bin", kTemplateRecordBytes, archive.templates_bin));
    describe("features", DescribeTable("features.bin", kFeatureRecordBytes, archive.features_bin));
    if (archive.manifest["tables"].contains("view_tree") && !archive.view_tree_bin.empty()) {
      describe("view_tree",
               DescribeTable("view_tree.bin", kViewLeaderRecordBytes, archive.view_tree_bin));
    }
  }
  std::vector<ZipEntry> entries = {{"mimetype", "application/x-layermod", false},
                                   {"manifest.json", archive.manifest.dump(2), true},
                                   {"templates.bin", std::move(archive.templates_bin), true},
                                   {"features.bin", std::move(archive.features_bin), true}};
  if (!archive.view_tree_bin.empty()) {
    entries.push_back({"view_tree.bin", std::move(archive.view_tree_bin), true});
  }
  for (ZipEntry& entry : archive.others) entries.push_back(std::move(entry));
  return WriteZip(entries);
}

void ExpectSameRecord(const TemplateRecord& actual, const TemplateRecord& expected) {
  SCOPED_TRACE("template " + std::to_string(expected.id));
  EXPECT_EQ(actual.id, expected.id);
  EXPECT_EQ(actual.obj_id, expected.obj_id);
  EXPECT_EQ(actual.layer_index, expected.layer_index);
  EXPECT_EQ(actual.layer_depth_mm, expected.layer_depth_mm);
  EXPECT_EQ(actual.view.azimuth_deg, expected.view.azimuth_deg);
  EXPECT_EQ(actual.view.elevation_deg, expected.view.elevation_deg);
  EXPECT_EQ(actual.view.roll_deg, expected.view.roll_deg);
  EXPECT_TRUE(actual.cam_from_model.R == expected.cam_from_model.R);
  EXPECT_TRUE(actual.cam_from_model.t == expected.cam_from_model.t);
  EXPECT_EQ(actual.bbox_px, expected.bbox_px);
  EXPECT_EQ(actual.centre_offset_px, expected.centre_offset_px);
  EXPECT_EQ(actual.centre_minus_surface_mm, expected.centre_minus_surface_mm);
  EXPECT_EQ(actual.depth_edge_count, expected.depth_edge_count);
  EXPECT_EQ(actual.status, expected.status);
  EXPECT_TRUE(actual.levels == expected.levels);
}

void ExpectSameManifest(const ArchiveManifest& actual, const ArchiveManifest& expected) {
  EXPECT_EQ(actual.format_version, kArchiveFormatVersion);
  EXPECT_EQ(actual.tool_version, expected.tool_version);
  EXPECT_EQ(actual.created_utc, expected.created_utc);
  EXPECT_EQ(actual.camera, expected.camera);
  ASSERT_EQ(actual.objects.size(), expected.objects.size());
  for (std::size_t i = 0; i < actual.objects.size(); ++i) {
    const ArchiveObject& a = actual.objects[i];
    const ArchiveObject& e = expected.objects[i];
    SCOPED_TRACE("object " + std::to_string(e.obj_id));
    EXPECT_EQ(a.obj_id, e.obj_id);
    EXPECT_EQ(a.name, e.name);
    EXPECT_EQ(a.mesh_file, e.mesh_file);
    EXPECT_EQ(a.mesh_hash, e.mesh_hash);
    EXPECT_EQ(a.units, e.units);
    EXPECT_TRUE(a.sphere.centre == e.sphere.centre);
    EXPECT_EQ(a.sphere.radius_mm, e.sphere.radius_mm);
    EXPECT_EQ(a.diameter_mm, e.diameter_mm);
    EXPECT_TRUE(a.bbox_min == e.bbox_min);
    EXPECT_TRUE(a.bbox_size == e.bbox_size);
    EXPECT_EQ(a.layer_depths_mm, e.layer_depths_mm);
    EXPECT_EQ(a.profile.depth_min_mm, e.profile.depth_min_mm);
    EXPECT_EQ(a.profile.depth_max_mm, e.profile.depth_max_mm);
    EXPECT_EQ(a.profile.views, e.profile.views);
    EXPECT_EQ(a.profile.features, e.profile.features);
    EXPECT_EQ(a.mesh.positions, e.mesh.positions);
    EXPECT_EQ(a.mesh.colors, e.mesh.colors);
    EXPECT_EQ(a.mesh.triangles, e.mesh.triangles);
  }
}

void ExpectSameArchive(const TemplateArchive& actual, const TemplateArchive& expected) {
  ExpectSameManifest(actual.manifest(), expected.manifest());
  ASSERT_EQ(actual.templates().size(), expected.templates().size());
  for (std::size_t i = 0; i < actual.templates().size(); ++i) {
    ExpectSameRecord(actual.templates()[i], expected.templates()[i]);
  }
  EXPECT_EQ(actual.ViewLeaders(), expected.ViewLeaders());
}

void ExpectRejected(std::string_view bytes, std::string_view phrase) {
  try {
    ReadArchiveBytes(bytes, "test.layermod");
    ADD_FAILURE() << "accepted, expected a FormatError containing '" << phrase << "'";
  } catch (const FormatError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'test.layermod': "), std::string::npos) << message;
    EXPECT_NE(message.find(phrase), std::string::npos)
        << "message: " << message << "\nexpected to contain: " << phrase;
  }
}

}  // namespace layermod::test
