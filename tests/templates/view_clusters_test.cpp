// SPDX-License-Identifier: MIT
#include "templates/view_clusters.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "util/error.h"

namespace layermod {
namespace {

Eigen::Matrix3d RotZ(double deg) {
  return Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ())
      .toRotationMatrix();
}

double AngleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const double c = std::clamp(((a.transpose() * b).trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / std::numbers::pi;
}

std::vector<TemplateRecord> RollsEvery5Degrees() {
  std::vector<TemplateRecord> records;
  for (int i = 0; i <= 18; ++i) {  // 0, 5, ..., 90 degrees
    TemplateRecord record;
    record.id = static_cast<std::uint32_t>(i);
    record.cam_from_model.R = RotZ(5.0 * i);
    records.push_back(record);
  }
  return records;
}

TEST(ViewClustersTest, NeighbouringRotationsShareAClusterLedByTheFirst) {
  const std::vector<TemplateRecord> records = RollsEvery5Degrees();
  const std::vector<ViewCluster> clusters = ClusterViews(records, 22.0);
  // Leaders at 0, 25, 50 and 75 degrees, each taking what lies within 22 degrees after it.
  ASSERT_EQ(clusters.size(), 4u);
  EXPECT_EQ(clusters[0].representative, 0u);
  EXPECT_EQ(clusters[0].members, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(clusters[1].representative, 5u);
  EXPECT_EQ(clusters[3].members, (std::vector<std::uint32_t>{15, 16, 17, 18}));
}

TEST(ViewClustersTest, EveryUsableTemplateIsInOneClusterNearItsRepresentative) {
  std::vector<TemplateRecord> records = RollsEvery5Degrees();
  records[7].status = TemplateStatus::kTooFewFeatures;
  const std::vector<ViewCluster> clusters = ClusterViews(records, 12.0);
  std::multiset<std::uint32_t> seen;
  for (const ViewCluster& cluster : clusters) {
    EXPECT_EQ(cluster.members.front(), cluster.representative);
    for (std::uint32_t member : cluster.members) {
      seen.insert(member);
      EXPECT_LE(AngleDeg(records[member].cam_from_model.R,
                         records[cluster.representative].cam_from_model.R),
                12.0 + 1e-9);
    }
  }
  EXPECT_EQ(seen.size(), records.size() - 1);
  EXPECT_EQ(seen.count(7), 0u);
  for (std::uint32_t i = 0; i < records.size(); ++i) {
    if (i != 7) {
      EXPECT_EQ(seen.count(i), 1u) << i;
    }
  }
}

TEST(ViewClustersTest, RefusesARadiusOutsideTheRange) {
  const std::vector<TemplateRecord> records = RollsEvery5Degrees();
  EXPECT_THROW(ClusterViews(records, 0.0), Error);
  EXPECT_THROW(ClusterViews(records, 181.0), Error);
  EXPECT_TRUE(ClusterViews({}, 20.0).empty());
}

}  // namespace
}  // namespace layermod
