// SPDX-License-Identifier: MIT
// Internal: the core's detections as the API's and back (for the CLI's JSON writer).
#pragma once

#include <layermod/detection.h>

#include "pipeline/detector.h"

namespace layermod::api {

DetectionResult FromCore(const layermod::DetectionResult& result, DetectionMode mode);
layermod::Detection ToCore(const Detection& detection);

}  // namespace layermod::api
