// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "match/matcher.h"
#include "pipeline/detector.h"

namespace layermod {

// Turns an object's raw matches (best first) into verified detections: initial pose from the
// template, ICP against the depth (when present), verification; duplicates of one instance
// (centres closer than the sphere radius) collapse to the best. At most `options.max_instances`.
// ICP and verification render `pose_mesh`: the object's mesh, or a coarser copy of it.
std::vector<Detection> PosesFromMatches(const std::vector<RawMatch>& matches,
                                        const TemplateArchive& archive, const ArchiveObject& object,
                                        const RenderMesh& pose_mesh, const Capture& capture,
                                        const DetectorOptions& options);

}  // namespace layermod
