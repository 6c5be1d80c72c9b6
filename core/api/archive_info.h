// SPDX-License-Identifier: MIT
// What `layermod inspect` shows of an archive (and the API's Archive::InfoJson returns): the
// manifest, the camera and per-layer template statistics.
#pragma once

#include <nlohmann/json.hpp>

#include "templates/archive.h"

namespace layermod {

// {"format_version", "tool_version", "created_utc", "camera", "templates", "objects": [{...,
// "views", "normal_frame" ("camera" or "viewing_ray", features/normal_frame.h), "layers":
// [{"index", "depth_mm", "templates", "weak", "view_clusters", "color_features", "normal_features",
// "depth_edges"}]}]}; feature and edge counts as {"min", "mean", "max"} over the layer's templates
// that are not weak; view_clusters 0 for a layer without a view tree.
nlohmann::json ArchiveInfoJson(const TemplateArchive& archive);

}  // namespace layermod
