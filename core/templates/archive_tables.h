// SPDX-License-Identifier: MIT
#pragma once

// The binary template and feature tables of a *.layermod archive (layout in
// docs/archive-format.md). Internal to the archive reader/writer; tests use it to build
// corrupt archives.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "templates/archive.h"

namespace layermod {

inline constexpr std::size_t kTemplateRecordBytes = 264;
inline constexpr std::size_t kFeatureRecordBytes = 6;
inline constexpr int kMaxStoredLevels = 4;  // level slots per template record
inline constexpr int kMaxLevelSizePx = 16384;

struct EncodedTables {
  std::string templates;  // templates.bin
  std::string features;   // features.bin
  std::uint64_t template_count = 0;
  std::uint64_t feature_count = 0;
};

// Encodes the records. Throws Error when a record cannot be stored (more than
// kMaxStoredLevels levels); values are checked separately by RecordValidator.
EncodedTables EncodeTables(std::span<const TemplateRecord> templates);

// Checks one record's values against the archive's objects: used before writing and after
// reading, so the writer never produces a file the reader refuses. Throws FormatError
// "template N: problem" (no file name).
class RecordValidator {
 public:
  explicit RecordValidator(const ArchiveManifest& manifest);
  void Check(const TemplateRecord& record, std::size_t index) const;

 private:
  std::unordered_map<std::int32_t, std::size_t> layer_count_;  // obj_id -> number of layers
};

// Decodes and validates both tables (sizes, feature offsets, every value). Throws FormatError
// naming the template and the problem (no file name).
std::vector<TemplateRecord> DecodeTables(std::string_view templates_bin,
                                         std::string_view features_bin,
                                         const ArchiveManifest& manifest);

}  // namespace layermod
