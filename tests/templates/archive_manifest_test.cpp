// SPDX-License-Identifier: MIT
#include "templates/archive_manifest.h"

#include <gtest/gtest.h>

#include <functional>

#include "archive_fixtures.h"
#include "templates/archive_tables.h"
#include "util/error.h"

namespace layermod {
namespace {

using Edit = std::function<void(nlohmann::json&)>;

// The synthetic archive with its manifest edited (tables untouched).
std::string WithManifest(const Edit& edit) {
  static const std::string kGood = [] {
    const TemplateArchive archive = test::MakeSyntheticArchive();
    return test::PackUnchecked(archive.manifest(), archive.templates());
  }();
  test::UnpackedArchive unpacked = test::Unpack(kGood);
  edit(unpacked.manifest);
  return test::Repack(unpacked, /*fix_tables=*/false);
}

TEST(ArchiveManifestTest, Crc32IsZlibsCrc) {
  EXPECT_EQ(Crc32("123456789"), 0xCBF43926u);  // the standard CRC-32 check value
  EXPECT_EQ(Crc32(""), 0u);
}

TEST(ArchiveManifestTest, JsonRoundTripKeepsTheManifest) {
  const TemplateArchive archive = test::MakeSyntheticArchive();
  const TableInfo templates{"templates.bin", kTemplateRecordBytes, 20, 20 * 264, 0xDEADBEEFu};
  const TableInfo features{"features.bin", kFeatureRecordBytes, 10, 60, 7u};
  const std::vector<MeshInfo> meshes = {{"mesh_3.bin", 8, 12, 336, 1u}, {"m7", 0, 0, 0, 2u}};
  const ViewTreeInfo view_tree = {{"view_tree.bin", kViewLeaderRecordBytes, 20, 80, 9u}, 17.5, 3};
  const nlohmann::json json = ManifestToJson(archive.manifest(), archive.templates(), templates,
                                             features, view_tree, meshes);
  const ParsedManifest parsed = ManifestFromJson(nlohmann::json::parse(json.dump()));
  ArchiveManifest without_meshes = archive.manifest();
  for (ArchiveObject& object : without_meshes.objects) object.mesh = RenderMesh();
  test::ExpectSameManifest(parsed.manifest, without_meshes);
  EXPECT_EQ(parsed.template_table, templates);
  EXPECT_EQ(parsed.feature_table, features);
  EXPECT_EQ(parsed.meshes, meshes);
  EXPECT_EQ(parsed.view_tree, view_tree);
  EXPECT_EQ(parsed.counts, CountsJson(archive.manifest(), archive.templates()));
  EXPECT_THROW(ManifestToJson(archive.manifest(), archive.templates(), templates, features,
                              view_tree, std::span(meshes).first(1)),
               Error);
}

TEST(ArchiveManifestTest, UnmodifiedManifestIsAccepted) {
  EXPECT_EQ(ReadArchiveBytes(WithManifest([](nlohmann::json&) {}), "x").templates().size(), 20u);
}

TEST(ArchiveManifestTest, OtherFormatVersionsAreRejectedFirst) {
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["format_version"] = 4; }),
                       "format version 4, this tool reads 1 to 3");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["format_version"] = 0; }),
                       "format version 0, this tool reads 1 to 3");
  // A future version may change anything else: the version error must come first.
  test::ExpectRejected(WithManifest([](nlohmann::json& m) {
                         m["format_version"] = 7;
                         m.erase("camera");
                         m["objects"] = "changed";
                       }),
                       "format version 7, this tool reads 1 to 3");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["format_version"] = -1; }),
                       "format version -1");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["format_version"] = "1"; }),
                       "manifest field 'format_version' must be an integer");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m.erase("format_version"); }),
                       "manifest field 'format_version' is missing");
}

TEST(ArchiveManifestTest, NonObjectManifestIsRejected) {
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m = nlohmann::json::array({1}); }),
                       "manifest is not a JSON object");
}

TEST(ArchiveManifestTest, MissingFieldsAreNamed) {
  const std::vector<std::pair<std::string, Edit>> cases = {
      {"tool_version", [](nlohmann::json& m) { m.erase("tool_version"); }},
      {"endianness", [](nlohmann::json& m) { m.erase("endianness"); }},
      {"camera", [](nlohmann::json& m) { m.erase("camera"); }},
      {"camera.fx", [](nlohmann::json& m) { m["camera"].erase("fx"); }},
      {"objects", [](nlohmann::json& m) { m.erase("objects"); }},
      {"objects[0].name", [](nlohmann::json& m) { m["objects"][0].erase("name"); }},
      {"objects[1].sphere.radius_mm",
       [](nlohmann::json& m) { m["objects"][1]["sphere"].erase("radius_mm"); }},
      {"objects[1].profile", [](nlohmann::json& m) { m["objects"][1].erase("profile"); }},
      {"objects[0].mesh", [](nlohmann::json& m) { m["objects"][0].erase("mesh"); }},
      {"objects[0].mesh.vertex_count",
       [](nlohmann::json& m) { m["objects"][0]["mesh"].erase("vertex_count"); }},
      {"counts", [](nlohmann::json& m) { m.erase("counts"); }},
      {"tables.features", [](nlohmann::json& m) { m["tables"].erase("features"); }},
      {"tables.templates.crc32",
       [](nlohmann::json& m) { m["tables"]["templates"].erase("crc32"); }},
  };
  for (const auto& [field, edit] : cases) {
    SCOPED_TRACE(field);
    test::ExpectRejected(WithManifest(edit), "manifest field '" + field + "' is missing");
  }
}

TEST(ArchiveManifestTest, WrongTypedFieldsAreNamed) {
  const std::vector<std::pair<std::string, Edit>> cases = {
      {"field 'camera.width' must be an integer",
       [](nlohmann::json& m) { m["camera"]["width"] = "640"; }},
      {"field 'camera.fx' must be a number",
       [](nlohmann::json& m) { m["camera"]["fx"] = nullptr; }},
      {"field 'objects' must be an array",
       [](nlohmann::json& m) {
         m["objects"] = {{"a", 1}};
       }},
      {"field 'objects[0]' is not a JSON object", [](nlohmann::json& m) { m["objects"][0] = 3; }},
      {"field 'objects[0].name' must be a string",
       [](nlohmann::json& m) { m["objects"][0]["name"] = 3; }},
      {"field 'objects[0].obj_id' must be an integer",
       [](nlohmann::json& m) { m["objects"][0]["obj_id"] = 3.5; }},
      {"field 'objects[0].obj_id' must be within",
       [](nlohmann::json& m) { m["objects"][0]["obj_id"] = 1ll << 40; }},
      {"field 'objects[0].layer_depths_mm' must be an array",
       [](nlohmann::json& m) { m["objects"][0]["layer_depths_mm"] = 600; }},
      {"field 'objects[0].layer_depths_mm' must hold numbers",
       [](nlohmann::json& m) { m["objects"][0]["layer_depths_mm"][1] = "700"; }},
      {"field 'objects[0].bbox_min_mm' must hold 3 numbers",
       [](nlohmann::json& m) {
         m["objects"][0]["bbox_min_mm"] = {1, 2};
       }},
      {"field 'objects[1].sphere.centre_mm' must hold 3 numbers",
       [](nlohmann::json& m) { m["objects"][1]["sphere"]["centre_mm"][2] = true; }},
      {"field 'objects[0].profile' is invalid: training profile field "
       "'features.pyramid_levels' must be an integer",
       [](nlohmann::json& m) { m["objects"][0]["profile"]["features"]["pyramid_levels"] = "2"; }},
      {"field 'tables.features.crc32' must be within",
       [](nlohmann::json& m) { m["tables"]["features"]["crc32"] = 1ll << 33; }},
      {"field 'tables.features.byte_size' must be a non-negative integer",
       [](nlohmann::json& m) { m["tables"]["features"]["byte_size"] = -6; }},
      {"field 'tables.templates.entry' must be a string",
       [](nlohmann::json& m) { m["tables"]["templates"]["entry"] = 1; }},
      {"field 'endianness' must be \"little\"", [](nlohmann::json& m) { m["endianness"] = "big"; }},
  };
  for (const auto& [phrase, edit] : cases) {
    SCOPED_TRACE(phrase);
    test::ExpectRejected(WithManifest(edit), phrase);
  }
}

TEST(ArchiveManifestTest, InvalidCameraIsRejected) {
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["camera"]["fx"] = -572.0; }),
                       "camera: focal lengths fx, fy must be positive");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["camera"]["height"] = 0; }),
                       "field 'camera.height' must be within 1..16384");
}

TEST(ArchiveManifestTest, InvalidObjectValuesAreRejected) {
  test::ExpectRejected(
      WithManifest([](nlohmann::json& m) { m["objects"][0]["bbox_size_mm"][1] = -1.0; }),
      "object 3: bounding box must be finite with a non-negative size");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["objects"][1]["units"] = "inch"; }),
                       "object 7: units: expected 'mm' or 'm', got 'inch'");
  test::ExpectRejected(
      WithManifest([](nlohmann::json& m) { m["objects"][1]["sphere"]["radius_mm"] = -2.0; }),
      "object 7: sphere must be finite with a non-negative radius");
  test::ExpectRejected(
      WithManifest([](nlohmann::json& m) { m["objects"][1]["layer_depths_mm"][0] = 0.0; }),
      "object 7: layer depths must be positive numbers");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["objects"][1]["obj_id"] = 3; }),
                       "object id 3 appears twice");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) {
                         m["objects"][0]["profile"]["depth_min_mm"] = 2000.0;  // above depth_max_mm
                       }),
                       "depth_min_mm must be below depth_max_mm");
}

TEST(ArchiveManifestTest, CountsMustMatchTheTables) {
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["counts"]["templates"] = 21; }),
                       "manifest counts do not match the template table");
  test::ExpectRejected(
      WithManifest([](nlohmann::json& m) { m["counts"]["objects"][1]["per_layer"][0] = 5; }),
      "manifest counts do not match the template table");
}

TEST(ArchiveManifestTest, RemovingALayerOrObjectOrphansTemplates) {
  test::ExpectRejected(
      WithManifest([](nlohmann::json& m) { m["objects"][0]["layer_depths_mm"].erase(2); }),
      "template 8: layer 2 but object 3 has 2 layers");
  test::ExpectRejected(WithManifest([](nlohmann::json& m) { m["objects"].erase(1); }),
                       "template 12: object 7 is not in the manifest");
}

}  // namespace
}  // namespace layermod
