// SPDX-License-Identifier: MIT
#include "geometry/resting_poses.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>

#include "geometry/pose.h"
#include "geometry/up_axis.h"
#include "support/matchers.h"

namespace layermod {
namespace {

using test::MatrixNear;

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;

  void Add(const TriangleMesh& other) {
    const int base = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (const auto& [a, b, c] : other.triangles) {
      triangles.push_back({a + base, b + base, c + base});
    }
  }
};

// An axis-aligned box from `low` to `low + size`, wound outwards; `shear_x_per_z` leans it.
TriangleMesh Box(const Eigen::Vector3d& size, const Eigen::Vector3d& low = Eigen::Vector3d::Zero(),
                 double shear_x_per_z = 0.0) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner(i & 1 ? size.x() : 0.0, i & 2 ? size.y() : 0.0,
                                 i & 4 ? size.z() : 0.0);
    mesh.vertices.push_back(low + corner + Eigen::Vector3d(shear_x_per_z * corner.z(), 0, 0));
  }
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

RestingPoses Rest(const TriangleMesh& mesh) {
  return FindRestingPoses(mesh.vertices, mesh.triangles);
}

// The share of the directions from `eye` that pass through a convex polygon (a fan of Van
// Oosterom and Strackee's triangles, over the whole sphere).
double Share(const std::vector<Eigen::Vector3d>& polygon, const Eigen::Vector3d& eye) {
  double solid_angle = 0.0;
  const Eigen::Vector3d a = polygon[0] - eye;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Eigen::Vector3d b = polygon[i] - eye;
    const Eigen::Vector3d c = polygon[i + 1] - eye;
    const double denominator = a.norm() * b.norm() * c.norm() + a.dot(b) * c.norm() +
                               a.dot(c) * b.norm() + b.dot(c) * a.norm();
    solid_angle += std::abs(2.0 * std::atan2(a.dot(b.cross(c)), denominator));
  }
  return solid_angle / (4.0 * kPi);
}

double TotalProbability(const RestingPoses& rest) {
  double total = 0.0;
  for (const RestingPose& pose : rest.poses) total += pose.probability;
  return total;
}

const RestingPose* PoseWithUp(const RestingPoses& rest, const Eigen::Vector3d& up) {
  for (const RestingPose& pose : rest.poses) {
    if (pose.up_in_model.isApprox(up, 1e-9)) return &pose;
  }
  return nullptr;
}

TEST(RestingPosesTest, ABoxRestsMostOftenOnItsLargestSides) {
  const RestingPoses rest = Rest(Box({100, 60, 20}));
  EXPECT_TRUE(rest.from_closed_mesh);
  EXPECT_THAT(rest.centre_of_mass, MatrixNear(Eigen::Vector3d(50, 30, 10), 1e-9));
  ASSERT_EQ(rest.poses.size(), 6u);
  EXPECT_EQ(rest.poses[0].axis_name.value_or("") + rest.poses[1].axis_name.value_or(""), "+z-z");
  EXPECT_NEAR(rest.poses[0].probability, rest.poses[1].probability, 1e-12);
  double total = 0.0;
  for (const RestingPose& pose : rest.poses) total += pose.probability;
  EXPECT_NEAR(total, 1.0, 1e-9);
  // Per up axis: the margin is half the shorter side of the face, the height half the box's
  // extent along the axis.
  const struct {
    const char* axis;
    double margin_mm;
    double height_mm;
  } expected[] = {{"+z", 30, 10}, {"-z", 30, 10}, {"+y", 10, 30},
                  {"-y", 10, 30}, {"+x", 10, 50}, {"-x", 10, 50}};
  for (const auto& [axis, margin_mm, height_mm] : expected) {
    SCOPED_TRACE(axis);
    const RestingPose* pose = PoseWithUp(rest, UpDirectionInModel(UprightFromUpAxis(axis)));
    ASSERT_NE(pose, nullptr);
    EXPECT_EQ(pose->axis_name, axis);
    EXPECT_NEAR(pose->stability_margin_mm, margin_mm, 1e-9);
    EXPECT_NEAR(pose->height_mm, height_mm, 1e-9);
  }
  EXPECT_GT(PoseWithUp(rest, Eigen::Vector3d::UnitZ())->probability,
            PoseWithUp(rest, Eigen::Vector3d::UnitY())->probability);
  EXPECT_GT(PoseWithUp(rest, Eigen::Vector3d::UnitY())->probability,
            PoseWithUp(rest, Eigen::Vector3d::UnitX())->probability);
}

// A 10 mm cube leaned over by 30 mm at the top: its centre of mass is beyond the bottom and the
// top faces, so it cannot stand on either; it lies on its sides.
TEST(RestingPosesTest, AFaceTheCentreOfMassIsNotAboveIsNotOffered) {
  const RestingPoses rest = Rest(Box({10, 10, 10}, Eigen::Vector3d::Zero(), 3.0));
  const Eigen::Vector3d& centre = rest.centre_of_mass;
  EXPECT_THAT(centre, MatrixNear(Eigen::Vector3d(20, 5, 5), 1e-9));
  ASSERT_EQ(rest.poses.size(), 4u);
  for (const RestingPose& pose : rest.poses) {
    EXPECT_LT(std::abs(pose.up_in_model.z()), 0.99) << "stands on its bottom or top";
    EXPECT_GT(pose.stability_margin_mm, 1.0);
  }
  EXPECT_NEAR(TotalProbability(rest), 1.0, 1e-9);
  const RestingPose* side = PoseWithUp(rest, Eigen::Vector3d::UnitY());
  ASSERT_NE(side, nullptr);
  EXPECT_NEAR(side->stability_margin_mm, 5.0 / std::sqrt(10.0), 1e-9);  // to the leaning edges
  // Off the bottom it tips over the edge at x = 10 onto the side x - 3z = 10, which gets both
  // shares; off the top onto the opposite side.
  const RestingPose* onto = PoseWithUp(rest, Eigen::Vector3d(-1, 0, 3).normalized());
  ASSERT_NE(onto, nullptr);
  const double lean = Share({{10, 0, 0}, {40, 0, 10}, {40, 10, 10}, {10, 10, 0}}, centre);
  const double bottom = Share({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}}, centre);
  EXPECT_NEAR(onto->probability, lean + bottom, 1e-9);
  const RestingPose* opposite = PoseWithUp(rest, Eigen::Vector3d(1, 0, -3).normalized());
  ASSERT_NE(opposite, nullptr);
  EXPECT_NEAR(opposite->probability, onto->probability, 1e-9);
}

// A 100 x 60 x 20 box with the edge between its top and its +y side cut off at 45 degrees: the
// centre of mass, dropped onto the cut, is beyond the cut's edge with the top, so a part that
// lands on the cut tips onto its top, and lying on the top gets the cut's share as well.
TEST(RestingPosesTest, APartTipsOffAnUnstableFaceOntoItsNeighbour) {
  const std::vector<Eigen::Vector3d> corners = {
      {0, 0, 0},    {100, 0, 0}, {0, 60, 0},    {100, 60, 0}, {0, 0, 20},
      {100, 0, 20}, {0, 55, 20}, {100, 55, 20}, {0, 60, 15},  {100, 60, 15}};
  const RestingPoses rest = FindRestingPoses(corners, {});  // convex: the hull's centre is right
  const Eigen::Vector3d& centre = rest.centre_of_mass;
  ASSERT_EQ(rest.poses.size(), 6u);
  EXPECT_EQ(PoseWithUp(rest, Eigen::Vector3d(0, -1, -1).normalized()), nullptr);
  const double cut = Share({{0, 55, 20}, {100, 55, 20}, {100, 60, 15}, {0, 60, 15}}, centre);
  const double top = Share({{0, 0, 20}, {100, 0, 20}, {100, 55, 20}, {0, 55, 20}}, centre);
  const double bottom = Share({{0, 0, 0}, {100, 0, 0}, {100, 60, 0}, {0, 60, 0}}, centre);
  EXPECT_GT(cut, 0.01);
  const RestingPose* on_top = PoseWithUp(rest, -Eigen::Vector3d::UnitZ());
  const RestingPose* on_bottom = PoseWithUp(rest, Eigen::Vector3d::UnitZ());
  ASSERT_NE(on_top, nullptr);
  ASSERT_NE(on_bottom, nullptr);
  EXPECT_NEAR(on_top->probability, top + cut, 1e-9);
  EXPECT_NEAR(on_bottom->probability, bottom, 1e-9);
  EXPECT_NEAR(TotalProbability(rest), 1.0, 1e-9);
}

// A box standing on two halves of a base that meet in a ridge along y, each tilted from flat: it
// rocks on either, and both are one pose with both shares. At 4 degrees each way both are named
// "+z" (8 degrees apart); at 2 degrees, turned 30 degrees away from any axis, they are unnamed
// but within kAxisNameToleranceDeg of each other.
TEST(RestingPosesTest, NearbyFacesAreOnePose) {
  for (const auto& [tilt_deg, turn_deg] : {std::pair{4.0, 0.0}, std::pair{2.0, 30.0}}) {
    SCOPED_TRACE(tilt_deg);
    const double drop = 50.0 * std::tan(DegToRad(tilt_deg));
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(DegToRad(turn_deg), Eigen::Vector3d::UnitY()).toRotationMatrix();
    std::vector<Eigen::Vector3d> corners = {
        {0, 0, 0},   {0, 60, 0},   {100, 0, 0},   {100, 60, 0},   {0, 0, 20},
        {0, 60, 20}, {100, 0, 20}, {100, 60, 20}, {50, 0, -drop}, {50, 60, -drop}};
    for (Eigen::Vector3d& p : corners) p = turn * p;
    const RestingPoses rest = FindRestingPoses(corners, {});
    const Eigen::Vector3d up = turn * Eigen::Vector3d::UnitZ();
    const RestingPose* base = nullptr;
    int near_up = 0;
    for (const RestingPose& pose : rest.poses) {
      if (pose.up_in_model.dot(up) > std::cos(DegToRad(2.0 * tilt_deg))) {
        ++near_up;
        base = &pose;
      }
    }
    ASSERT_EQ(near_up, 1);
    EXPECT_EQ(base->axis_name.has_value(), turn_deg == 0.0);
    EXPECT_NEAR(std::abs(base->up_in_model.dot(turn * Eigen::Vector3d::UnitX())),
                std::sin(DegToRad(tilt_deg)), 1e-9);  // one half's direction, not their mean
    const Eigen::Vector3d& centre = rest.centre_of_mass;
    const double left =
        Share({turn * Eigen::Vector3d(0, 0, 0), turn * Eigen::Vector3d(50, 0, -drop),
               turn * Eigen::Vector3d(50, 60, -drop), turn * Eigen::Vector3d(0, 60, 0)},
              centre);
    const double right =
        Share({turn * Eigen::Vector3d(50, 0, -drop), turn * Eigen::Vector3d(100, 0, 0),
               turn * Eigen::Vector3d(100, 60, 0), turn * Eigen::Vector3d(50, 60, -drop)},
              centre);
    EXPECT_NEAR(base->probability, left + right, 1e-9);
    EXPECT_EQ(rest.poses.size(), 6u);
    EXPECT_NEAR(TotalProbability(rest), 1.0, 1e-9);
  }
}

// Two separate boxes, one twice the other: the solid's centre of mass is not its hull's.
TEST(RestingPosesTest, CentreOfMassIsTheSolidsWhenTheMeshIsClosed) {
  TriangleMesh mesh = Box({10, 10, 10});
  mesh.Add(Box({20, 10, 10}, Eigen::Vector3d(20, 0, 0)));
  const Eigen::Vector3d solid_centre((5.0 * 1000 + 30.0 * 2000) / 3000, 5, 5);
  EXPECT_THAT(SolidCentreOfMass(mesh.vertices, mesh.triangles).value(),
              MatrixNear(solid_centre, 1e-9));
  const RestingPoses closed = Rest(mesh);
  EXPECT_TRUE(closed.from_closed_mesh);
  EXPECT_THAT(closed.centre_of_mass, MatrixNear(solid_centre, 1e-9));

  TriangleMesh open = mesh;
  open.triangles.pop_back();
  EXPECT_EQ(SolidCentreOfMass(open.vertices, open.triangles), std::nullopt);
  const RestingPoses from_hull = Rest(open);
  EXPECT_FALSE(from_hull.from_closed_mesh);
  EXPECT_THAT(from_hull.centre_of_mass, MatrixNear(Eigen::Vector3d(20, 5, 5), 1e-9));

  TriangleMesh inside_out = mesh;
  for (auto& triangle : inside_out.triangles) std::swap(triangle[1], triangle[2]);
  EXPECT_EQ(SolidCentreOfMass(inside_out.vertices, inside_out.triangles), std::nullopt);
}

TEST(RestingPosesTest, TheUpAxisIsCheckedAgainstTheLikelyPoses) {
  const RestingPoses rest = Rest(Box({100, 60, 20}));
  // +x and -x land 3 % of the time each: stable, but not a likely up axis.
  ASSERT_EQ(LikelyRestingPoses(rest).size(), 4u);
  EXPECT_TRUE(IsLikelyRestingUp(rest, UprightFromUpAxis("+z")));
  EXPECT_TRUE(IsLikelyRestingUp(rest, UprightFromUpAxis("-y")));
  EXPECT_FALSE(IsLikelyRestingUp(rest, UprightFromUpAxis("+x")));
  const std::optional<RestingPose> rare = RestingPoseAlong(rest, UprightFromUpAxis("+x"));
  ASSERT_TRUE(rare.has_value());
  EXPECT_EQ(rare->axis_name, "+x");
  EXPECT_LT(rare->probability, kLikelyRestProbability);
  const auto tilted = [](double angle_deg) {
    return Eigen::AngleAxisd(DegToRad(angle_deg), Eigen::Vector3d::UnitX()).toRotationMatrix();
  };
  EXPECT_TRUE(IsLikelyRestingUp(rest, tilted(kRestingUpToleranceDeg - 1.0)));
  EXPECT_FALSE(IsLikelyRestingUp(rest, tilted(kRestingUpToleranceDeg + 1.0)));
  EXPECT_FALSE(RestingPoseAlong(rest, tilted(45.0)).has_value());
}

// Over 100k vertices the hull is built from a thinned set; the corners of a box survive it.
TEST(RestingPosesTest, AMeshWithManyVerticesGivesTheSamePoses) {
  TriangleMesh dense = Box({100, 60, 20});
  for (int i = 0; i < 400; ++i) {
    for (int j = 0; j < 300; ++j) {
      dense.vertices.emplace_back(0.25 * i, 0.2 * j, 20.0);  // on the top, in no triangle
    }
  }
  ASSERT_GT(dense.vertices.size(), 100'000u);
  const RestingPoses expected = Rest(Box({100, 60, 20}));
  const RestingPoses rest = Rest(dense);
  ASSERT_EQ(rest.poses.size(), expected.poses.size());
  for (std::size_t i = 0; i < rest.poses.size(); ++i) {
    EXPECT_NEAR(rest.poses[i].probability, expected.poses[i].probability, 1e-9);
    EXPECT_NEAR(rest.poses[i].stability_margin_mm, expected.poses[i].stability_margin_mm, 1e-9);
  }
}

TEST(RestingPosesTest, PosesAreNamedAfterNearbyAxes) {
  // A box turned by 3 degrees about z still rests on +z; its sides are 3 degrees off +-x, +-y.
  TriangleMesh turned = Box({100, 60, 20});
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(DegToRad(3.0), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (Eigen::Vector3d& v : turned.vertices) v = turn * v;
  for (const RestingPose& pose : Rest(turned).poses) EXPECT_TRUE(pose.axis_name.has_value());

  RestingPose pose;
  pose.up_in_model = Eigen::Vector3d(0.12, -0.7, 0.7).normalized();
  EXPECT_EQ(RestingPoseName(pose), "tilted (0.12, -0.70, 0.70)");
  pose.axis_name = "-y";
  EXPECT_EQ(RestingPoseName(pose), "-y");
}

TEST(RestingPosesTest, AFlatMeshHasNoRestingPose) {
  const TriangleMesh square = {{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}},
                               {{0, 1, 2}, {0, 2, 3}}};
  const RestingPoses rest = Rest(square);
  EXPECT_TRUE(rest.poses.empty());
  EXPECT_FALSE(rest.from_closed_mesh);
  EXPECT_TRUE(LikelyRestingPoses(rest).empty());
}

}  // namespace
}  // namespace layermod
