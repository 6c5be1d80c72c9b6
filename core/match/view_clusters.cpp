// SPDX-License-Identifier: MIT
#include "match/view_clusters.h"

#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <string>

#include "util/error.h"

namespace layermod {

std::vector<ViewCluster> ClusterViews(std::span<const TemplateRecord> templates,
                                      double radius_deg) {
  if (!(radius_deg > 0.0 && radius_deg <= 180.0)) {
    throw Error("view cluster radius must be in (0, 180] degrees, got " +
                std::to_string(radius_deg));
  }
  // The angle between rotations A and B is at most r iff trace(A^T B) >= 1 + 2 cos r.
  const double min_trace = 1.0 + 2.0 * std::cos(radius_deg * std::numbers::pi / 180.0);
  std::vector<ViewCluster> clusters;
  std::vector<Eigen::Matrix3d> centres;  // the representatives' rotations, packed for the scan
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const TemplateRecord& record = templates[i];
    if (record.status == TemplateStatus::kTooFewFeatures) continue;
    const Eigen::Matrix3d& rotation = record.cam_from_model.R;
    std::size_t found = clusters.size();
    for (std::size_t c = 0; c < centres.size(); ++c) {
      if ((centres[c].cwiseProduct(rotation)).sum() >= min_trace) {
        found = c;
        break;
      }
    }
    const auto index = static_cast<std::uint32_t>(i);
    if (found == clusters.size()) {
      clusters.push_back({index, {index}});
      centres.push_back(rotation);
    } else {
      clusters[found].members.push_back(index);
    }
  }
  return clusters;
}

}  // namespace layermod
