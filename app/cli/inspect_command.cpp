// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/commands.h"
#include "templates/archive.h"

namespace layermod::cli {
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

nlohmann::json InspectJson(const TemplateArchive& archive) {
  const ArchiveManifest& manifest = archive.manifest();
  nlohmann::json json;
  json["format_version"] = manifest.format_version;
  json["tool_version"] = manifest.tool_version;
  json["created_utc"] = manifest.created_utc;
  const PinholeCamera& camera = manifest.camera;
  json["camera"] = {{"fx", camera.fx}, {"fy", camera.fy}, {"cx", camera.cx},
                    {"cy", camera.cy}, {"width", camera.width}, {"height", camera.height}};
  json["templates"] = archive.templates().size();
  for (const ArchiveObject& object : manifest.objects) {
    nlohmann::json entry = {{"obj_id", object.obj_id}, {"name", object.name},
                            {"mesh_file", object.mesh_file}, {"mesh_hash", object.mesh_hash},
                            {"units", object.units}, {"radius_mm", object.sphere.radius},
                            {"diameter_mm", object.diameter_mm}};
    entry["templates"] = archive.TemplatesOf(object.obj_id).size();
    for (std::size_t layer = 0; layer < object.layer_depths_mm.size(); ++layer) {
      const LayerStats stats = ComputeLayerStats(
          archive.TemplatesOf(object.obj_id, static_cast<int>(layer)), object.layer_depths_mm[layer]);
      entry["layers"].push_back({{"index", layer}, {"depth_mm", stats.depth_mm},
                                 {"templates", stats.templates}, {"weak", stats.weak},
                                 {"color_features", stats.color_features.ToJson()},
                                 {"normal_features", stats.normal_features.ToJson()},
                                 {"depth_edges", stats.depth_edges.ToJson()}});
    }
    json["objects"].push_back(entry);
  }
  return json;
}

void PrintText(const nlohmann::json& json) {
  const auto& camera = json["camera"];
  std::printf("format %d, written by layermod %s at %s\n", json["format_version"].get<int>(),
              json["tool_version"].get<std::string>().c_str(),
              json["created_utc"].get<std::string>().c_str());
  std::printf("camera fx %.3f fy %.3f cx %.3f cy %.3f  %dx%d\n", camera["fx"].get<double>(),
              camera["fy"].get<double>(), camera["cx"].get<double>(), camera["cy"].get<double>(),
              camera["width"].get<int>(), camera["height"].get<int>());
  std::printf("templates %zu\n", json["templates"].get<std::size_t>());
  for (const auto& object : json["objects"]) {
    std::printf("\nobject %d '%s' (%s, %s, hash %s)\n", object["obj_id"].get<int>(),
                object["name"].get<std::string>().c_str(),
                object["mesh_file"].get<std::string>().c_str(),
                object["units"].get<std::string>().c_str(),
                object["mesh_hash"].get<std::string>().c_str());
    std::printf("  radius %.2f mm, diameter %.2f mm, %zu templates\n",
                object["radius_mm"].get<double>(), object["diameter_mm"].get<double>(),
                object["templates"].get<std::size_t>());
    std::printf("  %5s %9s %9s %5s %18s %18s %18s\n", "layer", "depth_mm", "templates", "weak",
                "colour min/avg/max", "normal min/avg/max", "edges min/avg/max");
    for (const auto& layer : object["layers"]) {
      auto triple = [](const nlohmann::json& range) {
        char text[64];
        std::snprintf(text, sizeof(text), "%d/%.0f/%d", range["min"].get<int>(),
                      range["mean"].get<double>(), range["max"].get<int>());
        return std::string(text);
      };
      std::printf("  %5d %9.1f %9zu %5zu %18s %18s %18s\n", layer["index"].get<int>(),
                  layer["depth_mm"].get<double>(), layer["templates"].get<std::size_t>(),
                  layer["weak"].get<std::size_t>(), triple(layer["color_features"]).c_str(),
                  triple(layer["normal_features"]).c_str(), triple(layer["depth_edges"]).c_str());
    }
  }
}

}  // namespace

void AddInspectCommand(CLI::App& app) {
  auto archive_path = std::make_shared<std::string>();
  auto as_json = std::make_shared<bool>(false);
  CLI::App* command =
      app.add_subcommand("inspect", "Print an archive's manifest and template statistics");
  command->add_option("archive", *archive_path, "The .layermod file")->required();
  command->add_flag("--json", *as_json, "Print JSON instead of a table");
  command->callback([archive_path, as_json] {
    const nlohmann::json json = InspectJson(ReadArchive(*archive_path));
    if (*as_json) {
      std::cout << json.dump(2) << '\n';
    } else {
      PrintText(json);
    }
  });
}

}  // namespace layermod::cli
