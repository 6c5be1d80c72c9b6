// SPDX-License-Identifier: MIT
#include "api/archive_info.h"
#include "templates/training_profile.h"

#include <algorithm>
#include <span>

namespace layermod {
namespace {

struct Range {
  int min = 0;
  int max = 0;
  double sum = 0.0;
  std::size_t count = 0;

  void Add(int value) {
    min = count == 0 ? value : std::min(min, value);
    max = count == 0 ? value : std::max(max, value);
    sum += value;
    ++count;
  }
  double Mean() const { return count ? sum / static_cast<double>(count) : 0.0; }
  nlohmann::json ToJson() const { return {{"min", min}, {"mean", Mean()}, {"max", max}}; }
};

struct LayerStats {
  double depth_mm = 0.0;
  std::size_t templates = 0;
  std::size_t weak = 0;
  Range color_features;
  Range normal_features;
  Range depth_edges;
};

LayerStats ComputeLayerStats(std::span<const TemplateRecord> records, double depth_mm) {
  LayerStats stats;
  stats.depth_mm = depth_mm;
  for (const TemplateRecord& record : records) {
    ++stats.templates;
    if (record.status != TemplateStatus::kOk) {
      ++stats.weak;
      continue;
    }
    int color = 0;
    int normal = 0;
    for (const Feature& feature : record.levels.at(0).features) {
      (feature.modality == Modality::kColorGradient ? color : normal)++;
    }
    stats.color_features.Add(color);
    stats.normal_features.Add(normal);
    stats.depth_edges.Add(record.depth_edge_count);
  }
  return stats;
}

nlohmann::json ObjectJson(const TemplateArchive& archive, const ArchiveObject& object) {
  nlohmann::json entry = {{"obj_id", object.obj_id},
                          {"name", object.name},
                          {"mesh_file", object.mesh_file},
                          {"mesh_hash", object.mesh_hash},
                          {"units", object.units},
                          {"radius_mm", object.sphere.radius_mm},
                          {"diameter_mm", object.diameter_mm}};
  entry["templates"] = archive.TemplatesOf(object.obj_id).size();
  entry["views"] = ToJson(object.profile)["views"];  // the envelope and the up axis
  entry["normal_frame"] = NormalFrameName(object.profile.features.normal_frame);
  for (std::size_t layer = 0; layer < object.layer_depths_mm.size(); ++layer) {
    const LayerStats stats = ComputeLayerStats(
        archive.TemplatesOf(object.obj_id, static_cast<int>(layer)), object.layer_depths_mm[layer]);
    entry["layers"].push_back(
        {{"index", layer},
         {"depth_mm", stats.depth_mm},
         {"templates", stats.templates},
         {"weak", stats.weak},
         {"view_clusters", archive.ViewClustersOf(object.obj_id, static_cast<int>(layer)).size()},
         {"color_features", stats.color_features.ToJson()},
         {"normal_features", stats.normal_features.ToJson()},
         {"depth_edges", stats.depth_edges.ToJson()}});
  }
  return entry;
}

}  // namespace

nlohmann::json ArchiveInfoJson(const TemplateArchive& archive) {
  const ArchiveManifest& manifest = archive.manifest();
  nlohmann::json json;
  json["format_version"] = manifest.format_version;
  json["tool_version"] = manifest.tool_version;
  json["created_utc"] = manifest.created_utc;
  json["camera"] = CameraJson(manifest.camera);
  json["templates"] = archive.templates().size();
  for (const ArchiveObject& object : manifest.objects) {
    json["objects"].push_back(ObjectJson(archive, object));
  }
  return json;
}

}  // namespace layermod
