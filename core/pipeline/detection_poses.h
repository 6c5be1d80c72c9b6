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
// Detections the confidence model deems more likely right than wrong (confidence at least
// kLikelyConfidence) come first, then each group by Detection::ranking, best first (for
// std::stable_sort). The ranking alone let a pose the depth fits a little better but the model
// gives no chance (a clutter surface of the right shape) win over a confident right one at
// another place; the confidence alone ordered confident poses worse than the ranking does.
inline constexpr double kLikelyConfidence = 0.5;
bool RanksHigher(const Detection& a, const Detection& b);

// Turns an object's raw matches (best first) into verified detections: initial pose from the
// template, ICP against the depth (when present), verification; ordered best first (RanksHigher);
// duplicates of one instance (centres closer than the sphere radius) collapse to the best. At most
// `options.max_instances`. ICP and verification render `pose_mesh`: the object's mesh, or a coarser
// copy of it.
std::vector<Detection> PosesFromMatches(const std::vector<RawMatch>& matches,
                                        const TemplateArchive& archive, const ArchiveObject& object,
                                        const RenderMesh& pose_mesh, const Capture& capture,
                                        const GradientLabels& gradients,
                                        const DetectorOptions& options);

}  // namespace layermod
