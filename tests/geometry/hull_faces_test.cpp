// SPDX-License-Identifier: MIT
#include "geometry/hull_faces.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "geometry/pose.h"

namespace layermod {
namespace {

double PolygonArea(const HullFace& face) {
  Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < face.polygon.size(); ++i) {
    twice_area += (face.polygon[i] - face.polygon[0]).cross(face.polygon[i + 1] - face.polygon[0]);
  }
  return 0.5 * twice_area.dot(face.outward_normal);  // positive when counter-clockwise outside
}

void ExpectConvexCounterClockwise(const HullFace& face) {
  const std::size_t n = face.polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = face.polygon[i];
    const Eigen::Vector3d& b = face.polygon[(i + 1) % n];
    const Eigen::Vector3d& c = face.polygon[(i + 2) % n];
    EXPECT_GT((b - a).cross(c - b).dot(face.outward_normal), 0.0) << "corner " << i;
    EXPECT_NEAR(face.outward_normal.dot(a), face.plane_offset, 1e-9);
  }
}

// A box of 100 x 60 x 20 sampled on a grid, so every side is many coplanar triangles.
std::vector<Eigen::Vector3d> GriddedBox() {
  std::vector<Eigen::Vector3d> points;
  for (int x = 0; x <= 10; ++x) {
    for (int y = 0; y <= 6; ++y) {
      for (int z = 0; z <= 2; ++z) points.emplace_back(10.0 * x, 10.0 * y, 10.0 * z);
    }
  }
  return points;
}

TEST(HullFacesTest, ABoxHasSixRectangles) {
  const std::vector<HullFace> faces = MergeCoplanarTriangles(ComputeConvexHull(GriddedBox()));
  ASSERT_EQ(faces.size(), 6u);
  double total_area = 0.0;
  for (const HullFace& face : faces) {
    EXPECT_EQ(face.polygon.size(), 4u);
    ExpectConvexCounterClockwise(face);
    EXPECT_NEAR(face.outward_normal.cwiseAbs().maxCoeff(), 1.0, 1e-12);
    total_area += PolygonArea(face);
  }
  EXPECT_NEAR(total_area, 2.0 * (100 * 60 + 100 * 20 + 60 * 20), 1e-6);
}

// Across each side of a box's rectangle lies the face that side's outward direction points at.
TEST(HullFacesTest, EachSideKnowsTheFaceAcrossIt) {
  const std::vector<HullFace> faces = MergeCoplanarTriangles(ComputeConvexHull(GriddedBox()));
  ASSERT_EQ(faces.size(), 6u);
  for (const HullFace& face : faces) {
    ASSERT_EQ(face.neighbours.size(), face.polygon.size());
    for (std::size_t i = 0; i < face.polygon.size(); ++i) {
      SCOPED_TRACE(i);
      ASSERT_EQ(face.neighbours[i].size(), 1u);
      const Eigen::Vector3d edge = face.polygon[(i + 1) % face.polygon.size()] - face.polygon[i];
      const Eigen::Vector3d outward = edge.cross(face.outward_normal).normalized();
      EXPECT_NEAR(faces[face.neighbours[i][0]].outward_normal.dot(outward), 1.0, 1e-12);
    }
  }
}

// A prism over a regular 64-gon: its sides turn by 5.6 degrees, far more than the tolerance.
TEST(HullFacesTest, AFacetedCylinderKeepsItsSidesApart) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 64; ++i) {
    const double angle = 2.0 * kPi * i / 64.0;
    for (double z : {0.0, 30.0}) points.emplace_back(20 * std::cos(angle), 20 * std::sin(angle), z);
  }
  const std::vector<HullFace> faces = MergeCoplanarTriangles(ComputeConvexHull(points));
  ASSERT_EQ(faces.size(), 66u);
  int caps = 0;
  for (const HullFace& face : faces) {
    ExpectConvexCounterClockwise(face);
    if (std::abs(face.outward_normal.z()) > 0.5) {
      ++caps;
      EXPECT_EQ(face.polygon.size(), 64u);
      for (const std::vector<int>& across : face.neighbours) {
        ASSERT_EQ(across.size(), 1u);
        EXPECT_LT(std::abs(faces[across[0]].outward_normal.z()), 1e-9);  // a side, not a cap
      }
    } else {
      EXPECT_EQ(face.polygon.size(), 4u);
    }
  }
  EXPECT_EQ(caps, 2);
}

// A top raised by a fraction of a degree towards its middle (a scanned, slightly domed base) is
// still one face; a roof of a few degrees is not.
TEST(HullFacesTest, ANearlyFlatSideIsOneFace) {
  for (const auto& [slope_deg, top_faces] : {std::pair{0.3, 1u}, std::pair{3.0, 4u}}) {
    SCOPED_TRACE(slope_deg);
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 8; ++i) {
      points.emplace_back(i & 1 ? 100.0 : 0.0, i & 2 ? 60.0 : 0.0, i & 4 ? 20.0 : 0.0);
    }
    const double rise = 30.0 * std::tan(DegToRad(slope_deg));
    points.emplace_back(50.0, 30.0, 20.0 + rise);
    points.emplace_back(30.0, 30.0, 20.0 + rise);
    points.emplace_back(70.0, 30.0, 20.0 + rise);
    std::size_t up_faces = 0;
    for (const HullFace& face : MergeCoplanarTriangles(ComputeConvexHull(points))) {
      if (face.outward_normal.z() > 0.9) ++up_faces;
    }
    EXPECT_EQ(up_faces, top_faces);
  }
}

TEST(HullFacesTest, AnEmptyHullHasNoFaces) {
  EXPECT_TRUE(MergeCoplanarTriangles(ConvexHull{}).empty());
}

}  // namespace
}  // namespace layermod
