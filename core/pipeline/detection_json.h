// SPDX-License-Identifier: MIT
// Detections as JSON: what `layermod detect --json` writes and the API's users read. Poses in
// BOP's convention (cam_R_m2c row-major, cam_t_m2c in mm: x_in_cam = R * x_in_model + t).
#pragma once

#include <nlohmann/json.hpp>

#include "pipeline/detector.h"

namespace layermod {

nlohmann::ordered_json DetectionToJson(const Detection& detection);

// {"mode", "detections": [...] best first, "timings_ms": {...}}.
nlohmann::ordered_json DetectionResultToJson(const DetectionResult& result, DetectionMode mode);

nlohmann::ordered_json StageTimingsToJson(const StageTimings& timings);

}  // namespace layermod
