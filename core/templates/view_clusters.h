// SPDX-License-Identifier: MIT
#pragma once

// Neighbouring views of one object and depth layer grouped into clusters, so that a search over
// tens of thousands of templates can score one representative per cluster first and the other
// members only of the clusters whose representative scores best (a two-level view tree in the
// spirit of Konishi et al. 2019 and Ulrich et al. 2012: coarse views first, then their
// neighbours).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "templates/template_record.h"

namespace layermod {

struct ViewCluster {
  std::uint32_t representative = 0;    // index into the templates that were clustered
  std::vector<std::uint32_t> members;  // indices, the representative first
};

// Layers with this many templates or more get view clusters (the view tree) when an archive is
// built: full-sphere layers hold about 6,900, tabletop ones about 1,000 (which the flat search
// handles as fast).
inline constexpr std::size_t kViewTreeTemplates = 2000;
// Neighbouring views within this angle share a cluster: about ten per cluster at the full
// preset's 12 degree views and 15 degree rolls.
inline constexpr double kViewClusterRadiusDeg = 20.0;

// Greedy leader clustering of the templates' rotations (cam_from_model.R), in table order: a
// template joins the first cluster whose representative's rotation is within `radius_deg` of
// its own, or founds a new cluster. Templates with too few features are left out. Every other
// template is in exactly one cluster. Throws Error for a radius outside (0, 180].
std::vector<ViewCluster> ClusterViews(std::span<const TemplateRecord> templates, double radius_deg);

// The table form in which archives store clusters: for each of `template_count` templates the
// index of its cluster's representative, kNoViewCluster for templates in no cluster.
inline constexpr std::uint32_t kNoViewCluster = 0xFFFFFFFFu;
std::vector<std::uint32_t> ClusterLeaders(std::span<const ViewCluster> clusters,
                                          std::size_t template_count);

// The clusters a leader table describes, as ClusterViews orders them (by representative, members
// ascending), checked against the templates: one leader per template; a representative leads
// itself and comes before its members; templates with too few features are in no cluster and
// every other template is in one, or none is (a layer without a tree); members lie within
// `radius_deg` of their representative. Throws FormatError naming the template (by its id).
std::vector<ViewCluster> ClustersFromLeaders(std::span<const TemplateRecord> templates,
                                             std::span<const std::uint32_t> leaders,
                                             double radius_deg);

}  // namespace layermod
