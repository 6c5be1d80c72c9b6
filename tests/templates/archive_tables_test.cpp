// SPDX-License-Identifier: MIT
#include "templates/archive_tables.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <random>

#include "archive_fixtures.h"
#include "templates/byte_io.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Byte offsets inside a template record (docs/archive-format.md).
constexpr std::size_t kLevelCountAt = 11;
constexpr std::size_t kLevelSlotsAt = 168;
constexpr std::size_t kSlotBytes = 24;
constexpr std::size_t kSlotCountAt = 12;
constexpr std::size_t kSlotOffsetAt = 16;

const TemplateArchive& Synthetic() {
  static const TemplateArchive archive = test::MakeSyntheticArchive();
  return archive;
}

// The synthetic archive with its records edited, packed without the writer's checks.
std::string WithRecords(const std::function<void(std::vector<TemplateRecord>&)>& edit) {
  std::vector<TemplateRecord> templates = Synthetic().templates();
  edit(templates);
  return test::PackUnchecked(Synthetic().manifest(), templates);
}

// The synthetic archive with bytes of its tables edited (sizes and CRCs fixed up).
std::string WithTables(const std::function<void(std::string&, std::string&)>& edit) {
  test::UnpackedArchive unpacked =
      test::Unpack(test::PackUnchecked(Synthetic().manifest(), Synthetic().templates()));
  edit(unpacked.templates_bin, unpacked.features_bin);
  return test::Repack(unpacked);
}

template <typename T>
void Poke(std::string& bytes, std::size_t offset, T value) {
  std::string encoded;
  ByteWriter(encoded).Put(value);
  bytes.replace(offset, encoded.size(), encoded);
}

std::uint64_t PeekU64(const std::string& bytes, std::size_t offset) {
  return ByteReader(bytes, offset).Get<std::uint64_t>();
}

TEST(ArchiveTablesTest, TableSizesFollowTheLayout) {
  const auto& templates = Synthetic().templates();
  const EncodedTables tables = EncodeTables(templates);
  std::size_t features = 0;
  for (const auto& record : templates) {
    for (const auto& level : record.levels) features += level.features.size();
  }
  EXPECT_EQ(tables.template_count, templates.size());
  EXPECT_EQ(tables.feature_count, features);
  EXPECT_EQ(tables.templates.size(), templates.size() * kTemplateRecordBytes);
  EXPECT_EQ(tables.features.size(), features * kFeatureRecordBytes);
}

TEST(ArchiveTablesTest, RecordFieldsSitAtTheDocumentedOffsets) {
  const auto& templates = Synthetic().templates();
  const EncodedTables tables = EncodeTables(templates);
  const TemplateRecord& record = templates[13];
  ByteReader in(tables.templates, 13 * kTemplateRecordBytes);
  EXPECT_EQ(in.Get<std::uint32_t>(), 13u);
  EXPECT_EQ(in.Get<std::int32_t>(), 7);
  EXPECT_EQ(in.Get<std::uint16_t>(), record.layer_index);
  EXPECT_EQ(in.Get<std::uint8_t>(), static_cast<std::uint8_t>(record.status));
  EXPECT_EQ(in.Get<std::uint8_t>(), 2);  // level count
  EXPECT_EQ(in.Get<float>(), record.layer_depth_mm);
  EXPECT_EQ(in.Get<double>(), record.view.azimuth_deg);
  const std::size_t slot1 = 13 * kTemplateRecordBytes + kLevelSlotsAt + kSlotBytes;
  ByteReader level1(tables.templates, slot1);
  EXPECT_EQ(level1.Get<std::int32_t>(), 1);
  EXPECT_EQ(level1.Get<std::int32_t>(), record.levels[1].width);
  EXPECT_EQ(level1.Get<std::int32_t>(), record.levels[1].height);
  EXPECT_EQ(level1.Get<std::uint32_t>(), record.levels[1].features.size());
  const std::uint64_t offset = level1.Get<std::uint64_t>();
  // The feature at that offset is the first feature of level 1.
  ByteReader feature(tables.features, offset * kFeatureRecordBytes);
  EXPECT_EQ(feature.Get<std::int16_t>(), record.levels[1].features[0].x);
  EXPECT_EQ(feature.Get<std::int16_t>(), record.levels[1].features[0].y);
  EXPECT_EQ(feature.Get<std::uint8_t>(), record.levels[1].features[0].label);
}

TEST(ArchiveTablesTest, DecodeOfEncodeIsTheIdentity) {
  const EncodedTables tables = EncodeTables(Synthetic().templates());
  const std::vector<TemplateRecord> decoded =
      DecodeTables(tables.templates, tables.features, Synthetic().manifest());
  ASSERT_EQ(decoded.size(), Synthetic().templates().size());
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    test::ExpectSameRecord(decoded[i], Synthetic().templates()[i]);
  }
}

TEST(ArchiveTablesTest, MoreThanFourLevelsCannotBeEncoded) {
  std::vector<TemplateRecord> templates = Synthetic().templates();
  templates[0].levels.resize(5);
  EXPECT_THROW(EncodeTables(templates), Error);
}

TEST(ArchiveTablesTest, TableSizesMustBeWholeRecords) {
  const EncodedTables tables = EncodeTables(Synthetic().templates());
  EXPECT_THROW(DecodeTables(tables.templates + "x", tables.features, Synthetic().manifest()),
               FormatError);
  EXPECT_THROW(DecodeTables(tables.templates, tables.features + "x", Synthetic().manifest()),
               FormatError);
}

TEST(ArchiveTablesTest, ValidatorAcceptsGoodRecords) {
  const RecordValidator validator(Synthetic().manifest());
  for (std::size_t i = 0; i < Synthetic().templates().size(); ++i) {
    EXPECT_NO_THROW(validator.Check(Synthetic().templates()[i], i));
  }
}

using RecordEdit = std::function<void(std::vector<TemplateRecord>&)>;

TEST(ArchiveTablesTest, OutOfRangeRecordValuesAreRejected) {
  const std::vector<std::pair<std::string, RecordEdit>> cases = {
      {"template 4: id is 9", [](auto& t) { t[4].id = 9; }},
      {"template 0: object 99 is not in the manifest", [](auto& t) { t[0].obj_id = 99; }},
      {"template 13: layer 2 but object 7 has 2 layers", [](auto& t) { t[13].layer_index = 2; }},
      {"template 3: unknown status 5",
       [](auto& t) { t[3].status = static_cast<TemplateStatus>(5); }},
      {"template 2: layer depth must be a positive number",
       [](auto& t) { t[2].layer_depth_mm = static_cast<float>(kNaN); }},
      {"template 2: view angles are not finite",
       [](auto& t) { t[2].view.roll_deg = std::numeric_limits<double>::infinity(); }},
      {"template 2: centre offset is not finite",
       [](auto& t) { t[2].centre_minus_surface_mm = static_cast<float>(kNaN); }},
      {"template 2: pose is not finite", [](auto& t) { t[2].cam_from_model.R(1, 1) = kNaN; }},
      {"template 5: rotation is not orthonormal", [](auto& t) { t[5].cam_from_model.R *= 1.01; }},
      {"template 5: rotation is a reflection",
       [](auto& t) { t[5].cam_from_model.R.row(0) *= -1.0; }},
      {"template 6: bounding box has a negative size", [](auto& t) { t[6].bbox_px.width = -1; }},
      {"template 6: depth edge count is negative", [](auto& t) { t[6].depth_edge_count = -3; }},
      {"template 7: level 1 has pyramid level 3",
       [](auto& t) { t[7].levels[1].pyramid_level = 3; }},
      {"template 7: level 0 box -1x", [](auto& t) { t[7].levels[0].width = -1; }},
      {"template 7: level 0 box 20000x", [](auto& t) { t[7].levels[0].width = 20000; }},
      {"template 8: level 1 feature (",
       [](auto& t) {
         t[8].levels[1].features[5].x = static_cast<std::int16_t>(t[8].levels[1].width + 1);
       }},
      {"lies outside its box", [](auto& t) { t[8].levels[0].features[0].y = -1; }},
      {"template 9: level 0 feature label 8 is not 0..7",
       [](auto& t) { t[9].levels[0].features[70].label = 8; }},
      {"template 9: level 0 feature has unknown modality 2",
       [](auto& t) { t[9].levels[0].features[3].modality = static_cast<Modality>(2); }},
  };
  for (const auto& [phrase, edit] : cases) {
    SCOPED_TRACE(phrase);
    test::ExpectRejected(WithRecords(edit), phrase);
  }
}

TEST(ArchiveTablesTest, SmallRotationNoiseIsAccepted) {
  const std::string bytes = WithRecords([](auto& t) { t[5].cam_from_model.R(0, 0) += 2e-4; });
  EXPECT_NO_THROW(ReadArchiveBytes(bytes, "noisy.layermod"));
}

TEST(ArchiveTablesTest, CorruptLevelSlotsAreRejected) {
  test::ExpectRejected(WithTables([](std::string& templates, std::string&) {
                         templates[kTemplateRecordBytes + kLevelCountAt] = 5;
                       }),
                       "template 1: 5 pyramid levels, at most 4 allowed");
  test::ExpectRejected(WithTables([](std::string& templates, std::string&) {
                         templates[kLevelSlotsAt + 3 * kSlotBytes + 2] = 1;  // unused slot
                       }),
                       "template 0: unused pyramid level slots are not zero");
}

TEST(ArchiveTablesTest, FeatureOffsetsAndCountsBeyondTheTableAreRejected) {
  test::ExpectRejected(WithTables([](std::string& templates, std::string&) {
                         Poke<std::uint64_t>(templates,
                                             kTemplateRecordBytes + kLevelSlotsAt + kSlotOffsetAt,
                                             1'000'000'000ull);
                       }),
                       "template 1: level 0 features start at 1000000000, expected ");
  test::ExpectRejected(WithTables([](std::string& templates, std::string&) {
                         const std::size_t last = templates.size() - kTemplateRecordBytes;
                         Poke<std::uint32_t>(templates,
                                             last + kLevelSlotsAt + kSlotBytes + kSlotCountAt,
                                             0xFFFFFFFFu);
                       }),
                       "template 19: level 1 features run past the end of the feature table");
  test::ExpectRejected(
      WithTables([](std::string&, std::string& features) { features += std::string(6, '\0'); }),
      "but the templates use");
  // Offsets must follow each other: no two templates may share features.
  test::ExpectRejected(WithTables([](std::string& templates, std::string&) {
                         const std::size_t second = kTemplateRecordBytes + kLevelSlotsAt;
                         Poke<std::uint64_t>(templates, second + kSlotOffsetAt,
                                             PeekU64(templates, kLevelSlotsAt + kSlotOffsetAt));
                       }),
                       "template 1: level 0 features start at 0, expected ");
}

TEST(ArchiveTablesTest, CorruptFeatureBytesAreRejected) {
  test::ExpectRejected(WithTables([](std::string&, std::string& features) {
                         features[6 * 10 + 5] = 7;  // modality byte
                       }),
                       "feature has unknown modality 7");
  test::ExpectRejected(WithTables([](std::string&, std::string& features) {
                         features[6 * 10 + 4] = static_cast<char>(200);  // label byte
                       }),
                       "feature label 200 is not 0..7");
  test::ExpectRejected(WithTables([](std::string&, std::string& features) {
                         Poke<std::int16_t>(features, 6 * 11, -5);
                       }),
                       "template 0: level 0 feature (-5, ");
}

// Random damage behind valid checksums reaches the record validation: it must end in either a
// loaded archive (an unchecked bit such as a mantissa changed) or a FormatError, nothing else.
TEST(ArchiveTablesTest, RandomDamageBehindValidChecksumsNeverCrashes) {
  const test::UnpackedArchive good = test::Unpack(test::PackUnchecked(
      test::MakeSmallArchive().manifest(), test::MakeSmallArchive().templates()));
  std::mt19937 rng(5);
  int rejected = 0;
  constexpr int kRounds = 400;
  for (int round = 0; round < kRounds; ++round) {
    test::UnpackedArchive damaged = good;
    std::string& table = round % 2 == 0 ? damaged.templates_bin : damaged.features_bin;
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int i = 0; i < flips; ++i) {
      table[rng() % table.size()] = static_cast<char>(rng());
    }
    try {
      ReadArchiveBytes(test::Repack(damaged), "damaged.layermod");
    } catch (const FormatError& error) {
      ++rejected;
      ASSERT_NE(std::string(error.what()).find("'damaged.layermod': "), std::string::npos);
    }
  }
  EXPECT_GT(rejected, kRounds / 4);
}

}  // namespace
}  // namespace layermod
