// SPDX-License-Identifier: MIT
#include "templates/view_clusters.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "util/error.h"

namespace layermod {

namespace {

// The angle between rotations A and B is at most r iff trace(A^T B) >= 1 + 2 cos r.
double MinTrace(double radius_deg) {
  return 1.0 + 2.0 * std::cos(radius_deg * std::numbers::pi / 180.0);
}

void CheckRadius(double radius_deg) {
  if (!(radius_deg > 0.0 && radius_deg <= 180.0)) {
    throw Error("view cluster radius must be in (0, 180] degrees, got " +
                std::to_string(radius_deg));
  }
}

std::string Degrees(double degrees) {
  std::ostringstream text;
  text << degrees << " degrees";
  return text.str();
}

[[noreturn]] void Refuse(const TemplateRecord& record, const std::string& problem) {
  throw FormatError("view tree: template " + std::to_string(record.id) + " " + problem);
}

}  // namespace

std::vector<ViewCluster> ClusterViews(std::span<const TemplateRecord> templates,
                                      double radius_deg) {
  CheckRadius(radius_deg);
  const double min_trace = MinTrace(radius_deg);
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

std::vector<std::uint32_t> ClusterLeaders(std::span<const ViewCluster> clusters,
                                          std::size_t template_count) {
  std::vector<std::uint32_t> leaders(template_count, kNoViewCluster);
  for (const ViewCluster& cluster : clusters) {
    for (std::uint32_t member : cluster.members) leaders.at(member) = cluster.representative;
  }
  return leaders;
}

std::vector<ViewCluster> ClustersFromLeaders(std::span<const TemplateRecord> templates,
                                             std::span<const std::uint32_t> leaders,
                                             double radius_deg) {
  CheckRadius(radius_deg);
  if (leaders.size() != templates.size()) {
    throw FormatError("view tree: " + std::to_string(leaders.size()) + " entries for " +
                      std::to_string(templates.size()) + " templates");
  }
  const bool clustered = std::any_of(leaders.begin(), leaders.end(),
                                     [](std::uint32_t l) { return l != kNoViewCluster; });
  if (!clustered) return {};
  // Rounding of the stored rotations may move a member a hair past the radius.
  const double min_trace = MinTrace(radius_deg) - 1e-9;
  std::vector<ViewCluster> clusters;
  std::vector<std::uint32_t> cluster_of(templates.size(), kNoViewCluster);
  for (std::size_t i = 0; i < templates.size(); ++i) {
    const TemplateRecord& record = templates[i];
    const std::uint32_t leader = leaders[i];
    const bool usable = record.status != TemplateStatus::kTooFewFeatures;
    if (!usable) {
      if (leader != kNoViewCluster) Refuse(record, "has too few features but is in a cluster");
      continue;
    }
    if (leader == kNoViewCluster) Refuse(record, "is in no cluster of its clustered layer");
    if (leader > i) Refuse(record, "comes before its cluster's representative");
    const auto index = static_cast<std::uint32_t>(i);
    if (leader == index) {
      cluster_of[i] = static_cast<std::uint32_t>(clusters.size());
      clusters.push_back({index, {index}});
      continue;
    }
    if (cluster_of[leader] == kNoViewCluster) {
      Refuse(record, "is led by a template that does not lead a cluster");
    }
    const Eigen::Matrix3d& centre = templates[leader].cam_from_model.R;
    if (centre.cwiseProduct(record.cam_from_model.R).sum() < min_trace) {
      Refuse(record,
             "lies farther than " + Degrees(radius_deg) + " from its cluster's representative");
    }
    clusters[cluster_of[leader]].members.push_back(index);
  }
  return clusters;
}

}  // namespace layermod
