// SPDX-License-Identifier: MIT
#pragma once

// Neighbouring views of one object and depth layer grouped into clusters, so that a search over
// tens of thousands of templates can score one representative per cluster first and the other
// members only of the clusters whose representative scores best (a two-level view tree in the
// spirit of Konishi et al. 2019 and Ulrich et al. 2012: coarse views first, then their
// neighbours).

#include <cstdint>
#include <span>
#include <vector>

#include "templates/template_record.h"

namespace layermod {

struct ViewCluster {
  std::uint32_t representative = 0;    // index into the templates that were clustered
  std::vector<std::uint32_t> members;  // indices, the representative first
};

// Greedy leader clustering of the templates' rotations (cam_from_model.R), in table order: a
// template joins the first cluster whose representative's rotation is within `radius_deg` of
// its own, or founds a new cluster. Templates with too few features are left out. Every other
// template is in exactly one cluster. Throws Error for a radius outside (0, 180].
std::vector<ViewCluster> ClusterViews(std::span<const TemplateRecord> templates, double radius_deg);

}  // namespace layermod
