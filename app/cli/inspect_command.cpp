// SPDX-License-Identifier: MIT
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "api/archive_info.h"
#include "cli/commands.h"
#include "templates/archive.h"

namespace layermod::cli {
namespace {

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
    std::printf(
        "\nobject %d '%s' (%s, %s, hash %s)\n", object["obj_id"].get<int>(),
        object["name"].get<std::string>().c_str(), object["mesh_file"].get<std::string>().c_str(),
        object["units"].get<std::string>().c_str(), object["mesh_hash"].get<std::string>().c_str());
    std::printf("  radius %.2f mm, diameter %.2f mm, %zu templates\n",
                object["radius_mm"].get<double>(), object["diameter_mm"].get<double>(),
                object["templates"].get<std::size_t>());
    const auto& views = object["views"];
    const std::string up = views.contains("up_axis") ? views["up_axis"].get<std::string>()
                                                     : std::string("custom rotation");
    const std::string sampling = views["even_spacing_deg"].get<double>() > 0.0
                                     ? "even every " + views["even_spacing_deg"].dump() + " deg"
                                     : "azimuth " + views["azimuth"].get<std::string>();
    std::printf("  views: up axis %s, elevation %s, roll %s, %s\n", up.c_str(),
                views["elevation"].get<std::string>().c_str(),
                views["roll"].get<std::string>().c_str(), sampling.c_str());
    const bool ray_frame = object["normal_frame"] == "viewing_ray";
    std::printf("  depth normals quantized in the %s frame\n",
                ray_frame ? "viewing-ray" : "camera");
    std::printf("  %5s %9s %9s %5s %8s %18s %18s %18s\n", "layer", "depth_mm", "templates", "weak",
                "clusters", "colour min/avg/max", "normal min/avg/max", "edges min/avg/max");
    for (const auto& layer : object["layers"]) {
      auto triple = [](const nlohmann::json& range) {
        char text[64];
        std::snprintf(text, sizeof(text), "%d/%.0f/%d", range["min"].get<int>(),
                      range["mean"].get<double>(), range["max"].get<int>());
        return std::string(text);
      };
      // Layers without a view tree are searched flat.
      const auto clusters = layer["view_clusters"].get<std::size_t>();
      const std::string tree = clusters > 0 ? std::to_string(clusters) : "-";
      std::printf("  %5d %9.1f %9zu %5zu %8s %18s %18s %18s\n", layer["index"].get<int>(),
                  layer["depth_mm"].get<double>(), layer["templates"].get<std::size_t>(),
                  layer["weak"].get<std::size_t>(), tree.c_str(),
                  triple(layer["color_features"]).c_str(), triple(layer["normal_features"]).c_str(),
                  triple(layer["depth_edges"]).c_str());
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
    const nlohmann::json json = ArchiveInfoJson(ReadArchive(*archive_path));
    if (*as_json) {
      std::cout << json.dump(2) << '\n';
    } else {
      PrintText(json);
    }
  });
}

}  // namespace layermod::cli
