// SPDX-License-Identifier: MIT
// The view tree in the archive: built when an archive is made, stored in view_tree.bin, read
// back as stored, rebuilt for version 1 archives, and refused when it does not fit the
// templates.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "archive_fixtures.h"
#include "support/test_paths.h"
#include "templates/archive.h"
#include "templates/archive_manifest.h"
#include "templates/byte_io.h"
#include "templates/view_clusters.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

// One object with a layer large enough for a tree (layer 0) and a small one (layer 1).
TemplateArchive MakeTreeArchive() {
  test::SyntheticArchiveOptions options;
  options.obj_ids = {4};
  options.layers_per_object = {2};
  options.views_per_layer = static_cast<int>(kViewTreeTemplates) + 40;
  options.levels = 1;
  options.color_features = 4;
  options.normal_features = 3;
  const TemplateArchive large = test::MakeSyntheticArchive(options);
  // Layer 1 keeps only its first 50 templates: too few for a tree.
  std::vector<TemplateRecord> templates(large.templates().begin(),
                                        large.templates().begin() + options.views_per_layer + 50);
  return TemplateArchive(large.manifest(), templates);
}

std::string Bytes(const TemplateArchive& archive) {
  test::TempDir dir;
  WriteArchive(dir / "tree.layermod", archive);
  return ReadFileBytes(dir / "tree.layermod");
}

std::string LeaderBytes(const std::vector<std::uint32_t>& leaders) {
  std::string bytes;
  ByteWriter writer(bytes);
  for (std::uint32_t leader : leaders) writer.Put(leader);
  return bytes;
}

std::vector<std::uint32_t> Leaders(const std::string& bytes) {
  std::vector<std::uint32_t> leaders(bytes.size() / 4);
  ByteReader reader(bytes);
  for (std::uint32_t& leader : leaders) leader = reader.Get<std::uint32_t>();
  return leaders;
}

TEST(ArchiveViewTreeTest, LargeLayersAreClusteredWhenTheArchiveIsBuilt) {
  const TemplateArchive archive = MakeTreeArchive();
  const auto clusters = archive.ViewClustersOf(4, 0);
  const std::vector<ViewCluster> expected =
      ClusterViews(archive.TemplatesOf(4, 0), kViewClusterRadiusDeg);
  ASSERT_EQ(clusters.size(), expected.size());
  EXPECT_GT(clusters.size(), 10u);
  EXPECT_LT(clusters.size(), archive.TemplatesOf(4, 0).size());
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    EXPECT_EQ(clusters[c].members, expected[c].members) << c;
  }
  EXPECT_TRUE(archive.ViewClustersOf(4, 1).empty());  // 50 templates: searched flat
  EXPECT_TRUE(archive.ViewClustersOf(4, 2).empty());  // no such layer
  EXPECT_TRUE(archive.ViewClustersOf(9, 0).empty());  // no such object
  EXPECT_EQ(archive.ViewClusterCount(), clusters.size());
}

TEST(ArchiveViewTreeTest, TheTreeIsStoredAndReadBackAsStored) {
  const TemplateArchive archive = MakeTreeArchive();
  const std::string bytes = Bytes(archive);
  const test::UnpackedArchive unpacked = test::Unpack(bytes);
  EXPECT_EQ(unpacked.manifest["format_version"], kArchiveFormatVersion);
  EXPECT_EQ(unpacked.manifest["view_tree"]["clusters"], archive.ViewClusterCount());
  EXPECT_EQ(unpacked.manifest["view_tree"]["radius_deg"], kViewClusterRadiusDeg);
  EXPECT_EQ(Leaders(unpacked.view_tree_bin), archive.ViewLeaders());
  const TemplateArchive loaded = ReadArchiveBytes(bytes, "tree.layermod");
  test::ExpectSameArchive(loaded, archive);
  EXPECT_EQ(loaded.ViewClusterCount(), archive.ViewClusterCount());
}

// A member of a cluster with at least two: not its representative.
std::uint32_t SomeMember(std::span<const ViewCluster> clusters) {
  for (const ViewCluster& cluster : clusters) {
    if (cluster.members.size() >= 2) return cluster.members[1];
  }
  ADD_FAILURE() << "no cluster with two members";
  return 0;
}

TEST(ArchiveViewTreeTest, TheReaderUsesTheStoredClustersAsTheyAre) {
  // A member taken out of its cluster to lead one of its own is still a valid tree: the reader
  // keeps the stored grouping rather than clustering again.
  const TemplateArchive archive = MakeTreeArchive();
  test::UnpackedArchive unpacked = test::Unpack(Bytes(archive));
  std::vector<std::uint32_t> leaders = archive.ViewLeaders();
  const std::uint32_t member = SomeMember(archive.ViewClustersOf(4, 0));
  leaders[member] = member;
  unpacked.view_tree_bin = LeaderBytes(leaders);
  unpacked.manifest["view_tree"]["clusters"] = archive.ViewClusterCount() + 1;
  const TemplateArchive loaded = ReadArchiveBytes(test::Repack(unpacked), "x");
  EXPECT_EQ(loaded.ViewLeaders(), leaders);
  EXPECT_EQ(loaded.ViewClusterCount(), archive.ViewClusterCount() + 1);
}

TEST(ArchiveViewTreeTest, VersionOneArchivesLoadAndGetTheirTreeBuilt) {
  const TemplateArchive archive = MakeTreeArchive();
  test::UnpackedArchive unpacked = test::Unpack(Bytes(archive));
  unpacked.manifest["format_version"] = 1;
  unpacked.manifest.erase("view_tree");
  unpacked.manifest["tables"].erase("view_tree");
  unpacked.view_tree_bin.clear();
  const TemplateArchive loaded = ReadArchiveBytes(test::Repack(unpacked), "old.layermod");
  EXPECT_EQ(loaded.manifest().format_version, 1);
  EXPECT_EQ(loaded.ViewLeaders(), archive.ViewLeaders());
}

TEST(ArchiveViewTreeTest, AVersionTwoArchiveWithoutItsTreeIsRefused) {
  test::UnpackedArchive unpacked = test::Unpack(Bytes(MakeTreeArchive()));
  test::UnpackedArchive no_fields = unpacked;
  no_fields.manifest.erase("view_tree");
  test::ExpectRejected(test::Repack(no_fields), "manifest field 'view_tree' is missing");
  test::UnpackedArchive no_table = unpacked;
  no_table.manifest["tables"].erase("view_tree");
  test::ExpectRejected(test::Repack(no_table), "'tables.view_tree' is missing");
  test::UnpackedArchive no_entry = unpacked;
  no_entry.view_tree_bin.clear();
  test::ExpectRejected(test::Repack(no_entry, /*fix_tables=*/false),
                       "table 'view_tree.bin' is missing from the container");
}

TEST(ArchiveViewTreeTest, ATreeThatDoesNotFitItsTemplatesIsRefused) {
  const TemplateArchive archive = MakeTreeArchive();
  const test::UnpackedArchive good = test::Unpack(Bytes(archive));
  const std::vector<std::uint32_t> leaders = archive.ViewLeaders();
  const auto clusters = archive.ViewClustersOf(4, 0);
  const auto refused = [&](const std::vector<std::uint32_t>& edited, const std::string& phrase) {
    test::UnpackedArchive unpacked = good;
    unpacked.view_tree_bin = LeaderBytes(edited);
    test::ExpectRejected(test::Repack(unpacked), phrase);
  };
  // Leader clustering puts in the first cluster every view within the radius of its
  // representative (template 0), so a member of the second cluster lies farther from it.
  ASSERT_EQ(clusters[0].representative, 0u);
  const std::uint32_t second = clusters[1].members.back();
  std::vector<std::uint32_t> far = leaders;
  far[second] = 0;
  refused(far, "view tree: template " + std::to_string(second) +
                   " lies farther than 20 degrees from its cluster's representative");
  const auto last = static_cast<std::uint32_t>(archive.templates().size() - 1);
  std::vector<std::uint32_t> across = leaders;
  across[second] = last;
  refused(across,
          "is led by template " + std::to_string(last) + ", which is not of its object and layer");
  const std::uint32_t member = SomeMember(clusters);
  std::vector<std::uint32_t> not_leading = leaders;
  std::uint32_t later = member + 1;
  while (archive.templates()[later].status == TemplateStatus::kTooFewFeatures) ++later;
  not_leading[later] = member;
  refused(not_leading, "view tree: template " + std::to_string(later) +
                           " is led by a template that does not lead a cluster");
  std::vector<std::uint32_t> before = leaders;
  before[0] = clusters[1].representative;
  refused(before, "view tree: template 0 comes before its cluster's representative");
  std::vector<std::uint32_t> missing = leaders;
  missing[second] = kNoViewCluster;
  refused(missing, "view tree: template " + std::to_string(second) +
                       " is in no cluster of its clustered layer");
  std::vector<std::uint32_t> weak = leaders;
  weak[1] = 0;  // every fifth template from id 1 has too few features
  refused(weak, "view tree: template 1 has too few features but is in a cluster");
  const std::vector<std::uint32_t> short_table(leaders.begin(), leaders.end() - 1);
  refused(short_table, "view tree: " + std::to_string(leaders.size() - 1) + " entries for " +
                           std::to_string(leaders.size()) + " templates");
  test::UnpackedArchive count = good;
  count.manifest["view_tree"]["clusters"] = archive.ViewClusterCount() + 1;
  test::ExpectRejected(test::Repack(count), "view tree: the manifest counts");
  test::UnpackedArchive radius = good;
  radius.manifest["view_tree"]["radius_deg"] = 0;
  test::ExpectRejected(test::Repack(radius), "manifest field 'view_tree.radius_deg' must lie in");
}

}  // namespace
}  // namespace layermod
