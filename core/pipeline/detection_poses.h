// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "match/matcher.h"
#include "pipeline/detector.h"

namespace layermod {

// How detections are ordered, within an object and across objects: appearance, geometry and
// colour together. A high LineMOD score on a pose the depth or the colours contradict is worth
// less than a slightly lower score they confirm. Among the templates matched at one place, ICP
// brings neighbouring rotations to poses that pass the inlier test alike; how closely the depth
// fits (squared, so that it outweighs the few points of LineMOD score between them) is what
// picks the right one. score x depth_fit^2 x colour agreement, in percent; without depth the
// fit counts as 1.
double RankingScore(const Detection& detection, bool has_depth);
// Best first by Detection::ranking (for std::stable_sort).
bool RanksHigher(const Detection& a, const Detection& b);

// Turns an object's raw matches (best first) into verified detections: initial pose from the
// template, ICP against the depth (when present), verification; ranked best first by RankingScore;
// duplicates of one instance (centres closer than the sphere radius) collapse to the best. At most
// `options.max_instances`. ICP and verification render `pose_mesh`: the object's mesh, or a coarser
// copy of it.
std::vector<Detection> PosesFromMatches(const std::vector<RawMatch>& matches,
                                        const TemplateArchive& archive, const ArchiveObject& object,
                                        const RenderMesh& pose_mesh, const Capture& capture,
                                        const DetectorOptions& options);

}  // namespace layermod
