// SPDX-License-Identifier: MIT
#pragma once

// Synthetic archives and helpers to take them apart and corrupt them, shared by the template
// tests and the archive benchmark.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "templates/archive.h"
#include "templates/zip_container.h"

namespace layermod::test {

struct SyntheticArchiveOptions {
  std::vector<std::int32_t> obj_ids = {3, 7};
  std::vector<int> layers_per_object = {3, 2};
  int views_per_layer = 4;
  int levels = 2;
  int color_features = 80;  // per template at level 0 (more than 63 on purpose)
  int normal_features = 70;
  bool halve_features_per_level = true;  // false: every level gets the level-0 counts
  int weak_every = 5;                    // every n-th template is weak (0: none)
  std::uint32_t seed = 7;
};

// Two objects, several layers, random features, some weak templates, a small coloured mesh per
// object: every field differs from its default so that a field lost in the round trip shows.
TemplateArchive MakeSyntheticArchive(const SyntheticArchiveOptions& options = {});

// A tiny archive (one object, one layer, three templates) for byte-level corruption loops.
TemplateArchive MakeSmallArchive();

// Encodes manifest + records WITHOUT the writer's validation, so tests can produce archives
// with bad values that still have consistent sizes and checksums.
std::string PackUnchecked(const ArchiveManifest& manifest,
                          const std::vector<TemplateRecord>& templates);

// The entries of an archive file, to edit and pack again.
struct UnpackedArchive {
  nlohmann::json manifest;
  std::string templates_bin;
  std::string features_bin;
  std::string view_tree_bin;     // empty: no view_tree.bin entry (version 1)
  std::vector<ZipEntry> others;  // the mesh entries, in container order
};
UnpackedArchive Unpack(std::string_view bytes);
// Packs the entries; with `fix_tables` the manifest's table sizes, counts and CRCs are updated
// to match the (edited) tables.
std::string Repack(UnpackedArchive archive, bool fix_tables = true);

// Field-by-field comparison with gtest expectations.
void ExpectSameRecord(const TemplateRecord& actual, const TemplateRecord& expected);
void ExpectSameManifest(const ArchiveManifest& actual, const ArchiveManifest& expected);
void ExpectSameArchive(const TemplateArchive& actual, const TemplateArchive& expected);

// Reads `bytes` and expects a FormatError whose message names the file and contains `phrase`.
void ExpectRejected(std::string_view bytes, std::string_view phrase);

}  // namespace layermod::test
