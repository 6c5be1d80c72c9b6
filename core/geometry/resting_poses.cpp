// SPDX-License-Identifier: MIT
#include "geometry/resting_poses.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "geometry/convex_hull.h"
#include "geometry/hull_faces.h"
#include "geometry/pose.h"
#include "geometry/up_axis.h"
#include "util/error.h"

namespace layermod {
namespace {

// The centre of mass must clear a face's edges (and the hull's planes) by this fraction of the
// part's size to count as strictly inside: a part balanced on an edge, as far as rounding can
// tell, is not stable.
constexpr double kRelativeMinMargin = 1e-6;

// Every directed edge once, and its reverse once: closed and consistently oriented. Edges are
// looked up among their start vertex's few outgoing edges: a hash of every edge of a
// million-triangle mesh would take hundreds of MB.
bool IsClosedAndOriented(std::size_t vertex_count,
                         const std::vector<std::array<int, 3>>& triangles) {
  std::vector<int> start(vertex_count + 1, 0);
  for (const auto& c : triangles) {
    for (int corner : c) ++start[corner + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> fill(start.begin(), start.end() - 1);
  std::vector<int> edge_to(start.back());  // the end of each edge, grouped by start vertex
  for (const auto& c : triangles) {
    for (int i = 0; i < 3; ++i) edge_to[fill[c[i]]++] = c[(i + 1) % 3];
  }
  const auto count = [&](int from, int to) {
    return std::count(edge_to.begin() + start[from], edge_to.begin() + start[from + 1], to);
  };
  for (const auto& c : triangles) {
    for (int i = 0; i < 3; ++i) {
      const int from = c[i];
      const int to = c[(i + 1) % 3];
      if (count(from, to) != 1 || count(to, from) != 1) return false;
    }
  }
  return !triangles.empty();
}

// Hulls of larger point sets are built from HullCandidates: a dense scan of a curved part puts
// most of its million vertices on the hull, and the exact hull would take seconds.
constexpr std::size_t kExactHullMaxPoints = 100'000;
constexpr int kHullGridCells = 128;

// In a grid of kHullGridCells^2 columns along each axis, the lowest and highest point of each
// column. A point left out lies within its column's diagonal of the segment between those two,
// so the hull of what is kept is that close to the exact one (1/kHullGridCells of the bounding
// box's, about 1 mm on a 100 mm part), and at most 6 * kHullGridCells^2 points remain.
std::vector<Eigen::Vector3d> HullCandidates(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() <= kExactHullMaxPoints) return points;
  Eigen::Vector3d low = points.front();
  Eigen::Vector3d high = low;
  for (const Eigen::Vector3d& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Eigen::Vector3d cells_per_mm = (kHullGridCells / (high - low).array().max(1e-12)).matrix();
  const auto cell = [&](const Eigen::Vector3d& p, int axis) {
    return std::clamp(static_cast<int>((p[axis] - low[axis]) * cells_per_mm[axis]), 0,
                      kHullGridCells - 1);
  };
  std::vector<char> keep(points.size(), 0);
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    std::vector<int> lowest(static_cast<std::size_t>(kHullGridCells) * kHullGridCells, -1);
    std::vector<int> highest(lowest.size(), -1);
    for (int i = 0; i < static_cast<int>(points.size()); ++i) {
      const int column = cell(points[i], u) * kHullGridCells + cell(points[i], v);
      if (lowest[column] < 0 || points[i][axis] < points[lowest[column]][axis]) lowest[column] = i;
      if (highest[column] < 0 || points[i][axis] > points[highest[column]][axis]) {
        highest[column] = i;
      }
    }
    for (int i : lowest) {
      if (i >= 0) keep[i] = 1;
    }
    for (int i : highest) {
      if (i >= 0) keep[i] = 1;
    }
  }
  std::vector<Eigen::Vector3d> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (keep[i]) kept.push_back(points[i]);
  }
  return kept;
}

double HullSize(const std::vector<HullFace>& faces) {
  Eigen::Vector3d low = faces.front().polygon.front();
  Eigen::Vector3d high = low;
  for (const HullFace& face : faces) {
    for (const Eigen::Vector3d& p : face.polygon) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  }
  return (high - low).norm();
}

bool StrictlyInside(const std::vector<HullFace>& faces, const Eigen::Vector3d& point,
                    double margin) {
  return std::all_of(faces.begin(), faces.end(), [&](const HullFace& face) {
    return face.outward_normal.dot(point) < face.plane_offset - margin;
  });
}

// Van Oosterom and Strackee's formula for the solid angle of a triangle seen from the origin.
double TriangleSolidAngle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                          const Eigen::Vector3d& c) {
  const double la = a.norm();
  const double lb = b.norm();
  const double lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
  return std::abs(2.0 * std::atan2(numerator, denominator));
}

double FaceSolidAngle(const HullFace& face, const Eigen::Vector3d& eye) {
  double total = 0.0;
  const Eigen::Vector3d first = face.polygon[0] - eye;
  for (std::size_t i = 1; i + 1 < face.polygon.size(); ++i) {
    total += TriangleSolidAngle(first, face.polygon[i] - eye, face.polygon[i + 1] - eye);
  }
  return total;
}

// The distance from the centre of mass, dropped onto the face, to the nearest edge; negative
// when it falls outside.
double StabilityMargin(const HullFace& face, const Eigen::Vector3d& centre) {
  double margin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < face.polygon.size(); ++i) {
    const Eigen::Vector3d& from = face.polygon[i];
    const Eigen::Vector3d edge = face.polygon[(i + 1) % face.polygon.size()] - from;
    const Eigen::Vector3d inward = face.outward_normal.cross(edge).normalized();
    margin = std::min(margin, inward.dot(centre - from));  // the normal part drops out
  }
  return margin;
}

std::optional<std::string> AxisName(const Eigen::Vector3d& up_in_model) {
  for (const std::string& name : UpAxisNames()) {
    const Eigen::Vector3d axis = UpDirectionInModel(UprightFromUpAxis(name));
    if (axis.dot(up_in_model) >= std::cos(DegToRad(kAxisNameToleranceDeg))) return name;
  }
  return std::nullopt;
}

std::vector<RestingPose> StablePoses(const std::vector<HullFace>& faces,
                                     const Eigen::Vector3d& centre, double min_margin) {
  double total_angle = 0.0;
  for (const HullFace& face : faces) total_angle += FaceSolidAngle(face, centre);
  std::vector<RestingPose> poses;
  for (const HullFace& face : faces) {
    const double margin = StabilityMargin(face, centre);
    if (margin <= min_margin) continue;
    RestingPose pose;
    pose.up_in_model = -face.outward_normal;
    pose.probability = FaceSolidAngle(face, centre) / total_angle;
    pose.stability_margin_mm = margin;
    pose.height_mm = face.plane_offset - face.outward_normal.dot(centre);
    pose.axis_name = AxisName(pose.up_in_model);
    poses.push_back(std::move(pose));
  }
  std::stable_sort(poses.begin(), poses.end(), [](const RestingPose& a, const RestingPose& b) {
    return a.probability > b.probability;
  });
  return poses;
}

}  // namespace

std::optional<Eigen::Vector3d> SolidCentreOfMass(const std::vector<Eigen::Vector3d>& vertices,
                                                 const std::vector<std::array<int, 3>>& triangles) {
  if (!IsClosedAndOriented(vertices.size(), triangles)) return std::nullopt;
  // Tetrahedra from a point near the mesh to each triangle; their signed volumes add up to the
  // solid's. The point is near so that the terms stay small and cancel with little rounding.
  const Eigen::Vector3d& apex = vertices[triangles.front()[0]];
  double volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const auto& [a, b, c] : triangles) {
    const Eigen::Vector3d pa = vertices[a] - apex;
    const Eigen::Vector3d pb = vertices[b] - apex;
    const Eigen::Vector3d pc = vertices[c] - apex;
    const double tetra = pa.dot(pb.cross(pc)) / 6.0;
    volume += tetra;
    moment += tetra * (pa + pb + pc) / 4.0;
  }
  if (!(volume > 0.0)) return std::nullopt;
  return Eigen::Vector3d(apex + moment / volume);
}

RestingPoses FindRestingPoses(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<std::array<int, 3>>& triangles) {
  for (const Eigen::Vector3d& v : vertices) {
    if (!v.allFinite()) throw Error("resting poses: a vertex has a non-finite coordinate");
  }
  RestingPoses rest;
  const ConvexHull hull = ComputeConvexHull(HullCandidates(vertices));
  const std::vector<HullFace> faces = MergeCoplanarTriangles(hull);
  if (faces.empty()) return rest;
  const double min_margin = kRelativeMinMargin * HullSize(faces);
  // A self-intersecting mesh can be closed and still give a centre outside its hull.
  const std::optional<Eigen::Vector3d> solid = SolidCentreOfMass(vertices, triangles);
  rest.from_closed_mesh = solid && StrictlyInside(faces, *solid, min_margin);
  rest.centre_of_mass = rest.from_closed_mesh ? *solid : HullVolumeCentroid(hull);
  rest.poses = StablePoses(faces, rest.centre_of_mass, min_margin);
  return rest;
}

std::vector<RestingPose> LikelyRestingPoses(const RestingPoses& rest) {
  std::vector<RestingPose> likely;
  for (const RestingPose& pose : rest.poses) {
    if (pose.probability >= kLikelyRestProbability) likely.push_back(pose);
  }
  return likely;
}

std::optional<RestingPose> RestingPoseAlong(const RestingPoses& rest,
                                            const Eigen::Matrix3d& upright_from_model) {
  const Eigen::Vector3d up = UpDirectionInModel(upright_from_model).normalized();
  const double min_cos = std::cos(DegToRad(kRestingUpToleranceDeg));
  for (const RestingPose& pose : rest.poses) {  // most likely first
    if (pose.up_in_model.dot(up) >= min_cos) return pose;
  }
  return std::nullopt;
}

bool IsLikelyRestingUp(const RestingPoses& rest, const Eigen::Matrix3d& upright_from_model) {
  const std::optional<RestingPose> pose = RestingPoseAlong(rest, upright_from_model);
  return pose && pose->probability >= kLikelyRestProbability;
}

std::string RestingPoseName(const RestingPose& pose) {
  if (pose.axis_name) return *pose.axis_name;
  // Rounded first, so that a component just below zero reads 0.00 rather than -0.00.
  const Eigen::Vector3d up = (pose.up_in_model * 100.0).array().round() / 100.0 + 0.0;
  char text[64];
  std::snprintf(text, sizeof text, "tilted (%.2f, %.2f, %.2f)", up.x(), up.y(), up.z());
  return text;
}

}  // namespace layermod
