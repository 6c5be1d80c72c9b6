// SPDX-License-Identifier: MIT
// WriteArchive / ReadArchive / ReadArchiveBytes: round trip, atomic writing, the container and
// its tables. Field-level corruption is tested in archive_manifest_test.cpp and
// archive_tables_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "archive_fixtures.h"
#include "support/test_paths.h"
#include "templates/archive.h"
#include "templates/archive_manifest.h"
#include "templates/archive_tables.h"
#include "templates/zip_container.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {
namespace fs = std::filesystem;

int CountFiles(const fs::path& dir) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++count;
  return count;
}

std::string SmallArchiveBytes() {
  test::TempDir dir;
  WriteArchive(dir / "small.layermod", test::MakeSmallArchive());
  return ReadFileBytes(dir / "small.layermod");
}

TEST(ArchiveIoTest, RoundTripThroughAFileKeepsEveryField) {
  test::TempDir dir;
  const TemplateArchive original = test::MakeSyntheticArchive();
  WriteArchive(dir / "parts.layermod", original);
  const TemplateArchive loaded = ReadArchive(dir / "parts.layermod");
  test::ExpectSameArchive(loaded, original);
  EXPECT_EQ(loaded.TemplatesOf(7, 1).size(), 4u);
  EXPECT_EQ(loaded.TemplatesOf(7, 1).front().id, 16u);
}

TEST(ArchiveIoTest, RoundTripKeepsTemplatesWithoutLevels) {
  const TemplateArchive source = test::MakeSmallArchive();
  std::vector<TemplateRecord> templates = source.templates();
  templates[1].levels.clear();
  templates[1].status = TemplateStatus::kTooFewFeatures;
  const TemplateArchive original(source.manifest(), templates);
  test::TempDir dir;
  WriteArchive(dir / "a.layermod", original);
  test::ExpectSameArchive(ReadArchive(dir / "a.layermod"), original);
}

TEST(ArchiveIoTest, SameArchiveGivesSameBytes) {
  test::TempDir dir;
  const TemplateArchive archive = test::MakeSyntheticArchive();
  WriteArchive(dir / "a.layermod", archive);
  WriteArchive(dir / "b.layermod", archive);
  EXPECT_EQ(ReadFileBytes(dir / "a.layermod"), ReadFileBytes(dir / "b.layermod"));
}

TEST(ArchiveIoTest, FileStartsWithTheStoredMimetype) {
  const std::string bytes = SmallArchiveBytes();
  // Like EPUB/ODF: `file` and humans can recognise the type from the first bytes.
  EXPECT_EQ(bytes.substr(0, 4), "PK\x03\x04");
  EXPECT_EQ(bytes.substr(30, 8), "mimetype");
  EXPECT_EQ(bytes.substr(38, 22), "application/x-layermod");
}

TEST(ArchiveIoTest, ManifestIsReadableJsonWithCounts) {
  test::TempDir dir;
  const TemplateArchive archive = test::MakeSyntheticArchive();
  WriteArchive(dir / "a.layermod", archive);
  const std::string bytes = ReadFileBytes(dir / "a.layermod");
  const test::UnpackedArchive unpacked = test::Unpack(bytes);
  const nlohmann::json& manifest = unpacked.manifest;
  EXPECT_EQ(manifest["format_version"], kArchiveFormatVersion);
  EXPECT_EQ(manifest["endianness"], "little");
  EXPECT_EQ(manifest["camera"]["width"], 640);
  EXPECT_EQ(manifest["objects"][1]["obj_id"], 7);
  EXPECT_EQ(manifest["objects"][1]["layer_depths_mm"].size(), 2u);
  EXPECT_EQ(manifest["objects"][0]["profile"]["features"]["color_features"], 80);
  EXPECT_EQ(manifest["objects"][0]["profile"]["views"]["roll"], "-30:7.5:30");
  EXPECT_EQ(manifest["objects"][1]["mesh"]["entry"], "mesh_7.bin");
  EXPECT_EQ(manifest["objects"][1]["mesh"]["vertex_count"], 8);
  EXPECT_EQ(manifest["objects"][1]["mesh"]["triangle_count"], 12);
  ASSERT_EQ(unpacked.others.size(), 2u);
  EXPECT_EQ(unpacked.others[1].name, "mesh_7.bin");
  EXPECT_EQ(manifest["objects"][1]["mesh"]["crc32"], Crc32(unpacked.others[1].data));
  const nlohmann::json& counts = manifest["counts"];
  EXPECT_EQ(counts["templates"], 20);
  EXPECT_EQ(counts["weak_templates"], 4);  // ids 1, 6, 11, 16
  EXPECT_EQ(counts["objects"][0]["per_layer"], nlohmann::json({4, 4, 4}));
  EXPECT_EQ(counts["objects"][1]["templates"], 8);
  EXPECT_EQ(counts["objects"][1]["weak_templates"], 1);
  const nlohmann::json& templates = manifest["tables"]["templates"];
  EXPECT_EQ(templates["entry"], "templates.bin");
  EXPECT_EQ(templates["record_count"], 20);
  EXPECT_EQ(templates["record_size"], kTemplateRecordBytes);
  EXPECT_EQ(templates["byte_size"], unpacked.templates_bin.size());
  EXPECT_EQ(templates["crc32"], Crc32(unpacked.templates_bin));
  const nlohmann::json& features = manifest["tables"]["features"];
  EXPECT_EQ(features["record_count"], unpacked.features_bin.size() / 6);
  EXPECT_EQ(features["crc32"], Crc32(unpacked.features_bin));
  EXPECT_EQ(counts["features"], features["record_count"]);
}

TEST(ArchiveIoTest, MissingDirectoryIsIoErrorAndLeavesNoFile) {
  test::TempDir dir;
  const fs::path target = dir / "missing/a.layermod";
  try {
    WriteArchive(target, test::MakeSmallArchive());
    FAIL() << "expected IoError";
  } catch (const IoError& error) {
    EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos);
  }
  EXPECT_EQ(CountFiles(dir.path()), 0);
}

TEST(ArchiveIoTest, WritingOverAnArchiveReplacesItWholly) {
  test::TempDir dir;
  WriteArchive(dir / "a.layermod", test::MakeSyntheticArchive());
  const TemplateArchive small = test::MakeSmallArchive();
  WriteArchive(dir / "a.layermod", small);
  test::ExpectSameArchive(ReadArchive(dir / "a.layermod"), small);
  EXPECT_EQ(CountFiles(dir.path()), 1);  // no temporary left behind
}

TEST(ArchiveIoTest, InvalidContentIsNotWrittenAndKeepsTheOldFile) {
  test::TempDir dir;
  const TemplateArchive good = test::MakeSmallArchive();
  WriteArchive(dir / "a.layermod", good);
  std::vector<TemplateRecord> templates = good.templates();
  templates[2].cam_from_model.t.x() = std::numeric_limits<double>::quiet_NaN();
  const TemplateArchive bad(good.manifest(), templates);
  try {
    WriteArchive(dir / "a.layermod", bad);
    FAIL() << "expected Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("a.layermod"), std::string::npos) << message;
    EXPECT_NE(message.find("template 2: pose is not finite"), std::string::npos) << message;
  }
  test::ExpectSameArchive(ReadArchive(dir / "a.layermod"), good);
  EXPECT_EQ(CountFiles(dir.path()), 1);
}

TEST(ArchiveIoTest, MissingFileIsIoError) {
  test::TempDir dir;
  EXPECT_THROW(ReadArchive(dir / "none.layermod"), IoError);
  EXPECT_THROW(ReadArchive(dir.path()), IoError);
}

TEST(ArchiveIoTest, EmptyFileIsRejected) {
  test::TempDir dir;
  WriteFileAtomically(dir / "empty.layermod", "");
  try {
    ReadArchive(dir / "empty.layermod");
    FAIL() << "expected FormatError";
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find((dir / "empty.layermod").string() + "': empty file"),
              std::string::npos)
        << error.what();
  }
}

TEST(ArchiveIoTest, RandomBytesAreRejected) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::size_t size : {1u, 3u, 22u, 100u, 5000u}) {
    std::string bytes;
    for (std::size_t i = 0; i < size; ++i) bytes += static_cast<char>(byte(rng));
    if (bytes.starts_with("PK")) bytes[0] = 'Q';
    test::ExpectRejected(bytes, "no zip signature");
    test::ExpectRejected("PK\x03\x04" + bytes, "zip container");
  }
}

TEST(ArchiveIoTest, TruncationAnywhereIsRejected) {
  const std::string bytes = SmallArchiveBytes();
  ASSERT_GT(bytes.size(), 1000u);
  test::ExpectRejected(bytes.substr(0, 0), "empty file");
  test::ExpectRejected(bytes.substr(0, 3), "no zip signature");
  for (std::size_t size = 97; size < bytes.size(); size += 97) {
    SCOPED_TRACE("truncated to " + std::to_string(size) + " bytes");
    test::ExpectRejected(bytes.substr(0, size), "truncated");
  }
  test::ExpectRejected(bytes.substr(0, bytes.size() - 1), "truncated");
}

TEST(ArchiveIoTest, FlippedBytesNeverCrash) {
  const std::string good = SmallArchiveBytes();
  int rejected = 0;
  for (std::size_t offset = 0; offset < good.size(); ++offset) {
    std::string bytes = good;
    bytes[offset] = static_cast<char>(bytes[offset] ^ 0xA5);
    try {
      ReadArchiveBytes(bytes, "flipped.layermod");
    } catch (const FormatError& error) {
      ++rejected;
      ASSERT_NE(std::string(error.what()).find("'flipped.layermod': "), std::string::npos);
    }
  }
  // Only bytes nobody checks (entry times, "version made by", attributes...) may flip unseen.
  EXPECT_GT(rejected, static_cast<int>(good.size() * 8 / 10));
}

TEST(ArchiveIoTest, ForeignZipIsRejected) {
  test::ExpectRejected(WriteZip({{"readme.txt", "hello", true}}),
                       "not a LayerMOD archive (first entry is 'readme.txt', expected 'mimetype')");
}

TEST(ArchiveIoTest, WrongMimetypeIsRejected) {
  test::ExpectRejected(WriteZip({{"mimetype", "application/zip", false}}),
                       "mimetype is 'application/zip', expected 'application/x-layermod'");
  test::ExpectRejected(WriteZip({{"mimetype", "application/x-layermod\n", false}}), "mimetype is");
  test::ExpectRejected(WriteZip({{"mimetype", "application/x-layermod", true}}),
                       "'mimetype' is compressed");
}

TEST(ArchiveIoTest, MimetypeMustComeFirst) {
  const std::string bytes = SmallArchiveBytes();
  const test::UnpackedArchive unpacked = test::Unpack(bytes);
  test::ExpectRejected(WriteZip({{"manifest.json", unpacked.manifest.dump(), true},
                                 {"mimetype", "application/x-layermod", false}}),
                       "first entry is 'manifest.json'");
}

TEST(ArchiveIoTest, MissingOrBrokenManifestIsRejected) {
  test::ExpectRejected(WriteZip({{"mimetype", "application/x-layermod", false}}),
                       "'manifest.json' is missing");
  test::ExpectRejected(WriteZip({{"mimetype", "application/x-layermod", false},
                                 {"manifest.json", "{\"format_version\": 1,", true}}),
                       "'manifest.json' is not valid JSON");
}

TEST(ArchiveIoTest, MissingTableIsRejected) {
  const test::UnpackedArchive unpacked = test::Unpack(SmallArchiveBytes());
  test::ExpectRejected(WriteZip({{"mimetype", "application/x-layermod", false},
                                 {"manifest.json", unpacked.manifest.dump(), true},
                                 {"templates.bin", unpacked.templates_bin, true}}),
                       "table 'features.bin' is missing");
}

TEST(ArchiveIoTest, TableSizeMismatchIsRejected) {
  test::UnpackedArchive unpacked = test::Unpack(SmallArchiveBytes());
  nlohmann::json& table = unpacked.manifest["tables"]["templates"];
  table["record_count"] = table["record_count"].get<int>() + 1;
  table["byte_size"] = table["byte_size"].get<int>() + 264;
  test::ExpectRejected(test::Repack(unpacked, /*fix_tables=*/false),
                       "table 'templates.bin' holds 792 bytes, the manifest says 1056");
}

TEST(ArchiveIoTest, TableChecksumMismatchIsRejected) {
  test::UnpackedArchive unpacked = test::Unpack(SmallArchiveBytes());
  unpacked.manifest["tables"]["features"]["crc32"] =
      unpacked.manifest["tables"]["features"]["crc32"].get<std::uint32_t>() ^ 1u;
  test::ExpectRejected(test::Repack(unpacked, false), "table 'features.bin' is damaged (CRC-32");
  // A byte changed inside a table with the container re-packed around it.
  test::UnpackedArchive flipped = test::Unpack(SmallArchiveBytes());
  flipped.templates_bin[100] = static_cast<char>(flipped.templates_bin[100] ^ 1);
  test::ExpectRejected(test::Repack(flipped, false), "table 'templates.bin' is damaged (CRC-32");
}

TEST(ArchiveIoTest, HugeDeclaredCountsAreRejectedWithoutAllocating) {
  const test::UnpackedArchive good = test::Unpack(SmallArchiveBytes());
  test::UnpackedArchive count = good;
  count.manifest["tables"]["features"]["record_count"] = 1'000'000'000'000'000ull;
  test::ExpectRejected(test::Repack(count, false),
                       "1000000000000000 records of 6 bytes do not make");
  test::UnpackedArchive size = good;
  size.manifest["tables"]["features"]["record_count"] = 1'000'000'000'000ull;
  size.manifest["tables"]["features"]["byte_size"] = 6'000'000'000'000ull;
  test::ExpectRejected(test::Repack(size, false), "the manifest says 6000000000000");
  test::UnpackedArchive huge = good;
  huge.manifest["tables"]["templates"]["record_count"] = 1e30;
  test::ExpectRejected(test::Repack(huge, false),
                       "field 'tables.templates.record_count' must be a non-negative integer");
}

TEST(ArchiveIoTest, WrongRecordSizeIsRejected) {
  test::UnpackedArchive unpacked = test::Unpack(SmallArchiveBytes());
  unpacked.manifest["tables"]["templates"]["record_size"] = 100;
  test::ExpectRejected(test::Repack(unpacked, false),
                       "table 'templates.bin' has records of 100 bytes, expected 264");
}

}  // namespace
}  // namespace layermod
