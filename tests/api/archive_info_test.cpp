// SPDX-License-Identifier: MIT
// ArchiveInfoJson (what `layermod inspect` prints) on a hand-made archive: counts, weak
// templates and feature ranges are exact.
#include "api/archive_info.h"

#include <gtest/gtest.h>

namespace layermod {
namespace {

TemplateRecord Record(std::uint32_t id, int layer, int color, int normal, int edges, bool weak) {
  TemplateRecord record;
  record.id = id;
  record.obj_id = 3;
  record.layer_index = static_cast<std::uint16_t>(layer);
  record.status = weak ? TemplateStatus::kTooFewFeatures : TemplateStatus::kOk;
  record.depth_edge_count = edges;
  record.levels.resize(1);
  for (int i = 0; i < color + normal; ++i) {
    Feature feature;
    feature.modality = i < color ? Modality::kColorGradient : Modality::kDepthNormal;
    record.levels[0].features.push_back(feature);
  }
  return record;
}

TemplateArchive HandMadeArchive() {
  ArchiveManifest manifest;
  manifest.tool_version = "9.9.9";
  manifest.created_utc = "2024-01-01T00:00:00Z";
  manifest.camera = {500.0, 501.0, 320.0, 240.0, 640, 480};
  ArchiveObject object;
  object.obj_id = 3;
  object.name = "part";
  object.mesh_file = "part.ply";
  object.sphere.radius_mm = 40.0;
  object.diameter_mm = 80.0;
  object.layer_depths_mm = {600.0, 800.0};
  manifest.objects.push_back(object);
  return TemplateArchive(manifest,
                         {Record(0, 0, 10, 20, 100, false), Record(1, 0, 30, 40, 300, false),
                          Record(2, 0, 0, 0, 0, true), Record(3, 1, 5, 6, 7, false)});
}

TEST(ArchiveInfoTest, CountsTemplatesAndFeatureRangesPerLayer) {
  const nlohmann::json info = ArchiveInfoJson(HandMadeArchive());
  EXPECT_EQ(info["tool_version"], "9.9.9");
  EXPECT_EQ(info["templates"], 4);
  EXPECT_EQ(info["camera"]["fy"], 501.0);
  ASSERT_EQ(info["objects"].size(), 1u);
  const nlohmann::json& object = info["objects"][0];
  EXPECT_EQ(object["name"], "part");
  EXPECT_EQ(object["radius_mm"], 40.0);
  EXPECT_EQ(object["templates"], 4);
  ASSERT_EQ(object["layers"].size(), 2u);
  const nlohmann::json& near = object["layers"][0];
  EXPECT_EQ(near["depth_mm"], 600.0);
  EXPECT_EQ(near["templates"], 3);
  EXPECT_EQ(near["weak"], 1);           // left out of the ranges
  EXPECT_EQ(near["view_clusters"], 0);  // too few templates for a view tree
  EXPECT_EQ(near["color_features"], (nlohmann::json{{"min", 10}, {"mean", 20.0}, {"max", 30}}));
  EXPECT_EQ(near["normal_features"], (nlohmann::json{{"min", 20}, {"mean", 30.0}, {"max", 40}}));
  EXPECT_EQ(near["depth_edges"], (nlohmann::json{{"min", 100}, {"mean", 200.0}, {"max", 300}}));
  EXPECT_EQ(object["layers"][1]["templates"], 1);
  EXPECT_EQ(object["layers"][1]["depth_edges"]["mean"], 7.0);
}

}  // namespace
}  // namespace layermod
