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

struct Margin {
  double distance_mm = 0.0;  // negative when the centre falls outside
  std::size_t side = 0;      // of the polygon, from corner `side` to the next
};

// The distance from the centre of mass, dropped onto the face, to the nearest side, and that
// side. When the centre falls outside, it is the side the centre is farthest beyond.
Margin StabilityMargin(const HullFace& face, const Eigen::Vector3d& centre) {
  Margin margin{std::numeric_limits<double>::infinity(), 0};
  for (std::size_t i = 0; i < face.polygon.size(); ++i) {
    const Eigen::Vector3d& from = face.polygon[i];
    const Eigen::Vector3d edge = face.polygon[(i + 1) % face.polygon.size()] - from;
    const Eigen::Vector3d inward = face.outward_normal.cross(edge).normalized();
    const double distance = inward.dot(centre - from);  // the normal part drops out
    if (distance < margin.distance_mm) margin = {distance, i};
  }
  return margin;
}

// The face a part lying on `from` tips onto. It tips over the side the centre of mass is
// farthest beyond (StabilityMargin): turning about a side lowers the centre at a rate equal to
// that distance, so this is the way gravity's torque is largest, and it is the side nearest the
// projected centre whenever that is nearest to a side rather than a corner. (The side crossed on
// the way from the face's centroid to the projected centre would depend on the polygon's shape
// far from where the part pivots.) While it turns about the side, the direction towards the
// table sweeps from the face's normal towards the side's outward direction; the neighbour
// normal it reaches first (the smallest turn) is the face that lands. -1 when `from` has no
// neighbour.
int FaceTippedOnto(const std::vector<HullFace>& faces, int from, std::size_t side) {
  const HullFace& face = faces[from];
  std::vector<int> candidates = face.neighbours[side];
  if (candidates.empty()) {  // no hull edge was matched to that side: any neighbour
    for (const std::vector<int>& across : face.neighbours) {
      candidates.insert(candidates.end(), across.begin(), across.end());
    }
  }
  const Eigen::Vector3d edge = face.polygon[(side + 1) % face.polygon.size()] - face.polygon[side];
  const Eigen::Vector3d outward = edge.cross(face.outward_normal).normalized();
  int onto = -1;
  double smallest_turn = std::numeric_limits<double>::infinity();
  for (int candidate : candidates) {
    const Eigen::Vector3d& normal = faces[candidate].outward_normal;
    double turn = std::atan2(normal.dot(outward), normal.dot(face.outward_normal));
    if (turn < 0.0) turn += 2.0 * kPi;  // leans the other way: reached last
    if (turn < smallest_turn) {
      smallest_turn = turn;
      onto = candidate;
    }
  }
  return onto;
}

// A chain of tips this long is taken to be broken. The centre of mass drops with every tip, so a
// real chain never revisits a face (a revisit is caught as well); the cap bounds the work should
// rounding or a face's tolerance (kCoplanarAngleDeg) ever mislead the walk.
constexpr std::size_t kMaxTips = 10'000;
constexpr int kUnresolved = -1;
constexpr int kOnChain = -2;

// The stable face whose up direction is nearest to the face's: where a part is taken to end when
// its chain of tips cannot be followed.
int NearestStableFace(const std::vector<HullFace>& faces, const std::vector<char>& stable, int f) {
  int nearest = kUnresolved;
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t g = 0; g < faces.size(); ++g) {
    const double alignment = faces[g].outward_normal.dot(faces[f].outward_normal);
    if (stable[g] && alignment > best) {
      best = alignment;
      nearest = static_cast<int>(g);
    }
  }
  return nearest;
}

// For each face, the stable face a part that lands on it comes to rest on, by quasi-static
// draining (Moll and Erdmann, "Manipulation of pose distributions", 2002): from an unstable face
// it tips onto FaceTippedOnto, and so on. Chains share their ends, so this is linear in the faces.
std::vector<int> RestingFaces(const std::vector<HullFace>& faces, const std::vector<char>& stable,
                              const std::vector<int>& tipped_onto) {
  std::vector<int> rests_on(faces.size(), kUnresolved);
  std::vector<int> chain;
  for (std::size_t start = 0; start < faces.size(); ++start) {
    chain.clear();
    int face = static_cast<int>(start);
    int end = kUnresolved;
    while (true) {
      if (rests_on[face] >= 0) {
        end = rests_on[face];
        break;
      }
      if (stable[face]) {
        end = face;
        break;
      }
      if (rests_on[face] == kOnChain || tipped_onto[face] < 0 || chain.size() >= kMaxTips) break;
      rests_on[face] = kOnChain;
      chain.push_back(face);
      face = tipped_onto[face];
    }
    for (int f : chain) rests_on[f] = end >= 0 ? end : NearestStableFace(faces, stable, f);
    if (stable[start]) rests_on[start] = static_cast<int>(start);
  }
  return rests_on;
}

std::optional<std::string> AxisName(const Eigen::Vector3d& up_in_model) {
  for (const std::string& name : UpAxisNames()) {
    const Eigen::Vector3d axis = UpDirectionInModel(UprightFromUpAxis(name));
    if (axis.dot(up_in_model) >= std::cos(DegToRad(kAxisNameToleranceDeg))) return name;
  }
  return std::nullopt;
}

void SortMostLikelyFirst(std::vector<RestingPose>& poses) {
  std::stable_sort(poses.begin(), poses.end(), [](const RestingPose& a, const RestingPose& b) {
    return a.probability > b.probability;
  });
}

// Poses within kAxisNameToleranceDeg of a more likely one, or named after the same axis, are one
// pose: a scanned base is often several faces a degree or two apart, and a part set down on it
// is the same way up whichever of them touches. The most likely keeps its direction and margins
// and gets their summed probability. `poses` is most likely first.
std::vector<RestingPose> GroupNearbyPoses(const std::vector<RestingPose>& poses) {
  const double min_cos = std::cos(DegToRad(kAxisNameToleranceDeg));
  std::vector<RestingPose> groups;
  for (const RestingPose& pose : poses) {
    const auto same = std::find_if(groups.begin(), groups.end(), [&](const RestingPose& group) {
      return group.up_in_model.dot(pose.up_in_model) >= min_cos ||
             (group.axis_name && group.axis_name == pose.axis_name);
    });
    if (same == groups.end()) {
      groups.push_back(pose);
    } else {
      same->probability += pose.probability;
    }
  }
  SortMostLikelyFirst(groups);
  return groups;
}

std::vector<RestingPose> StablePoses(const std::vector<HullFace>& faces,
                                     const Eigen::Vector3d& centre, double min_margin) {
  std::vector<double> solid_angles(faces.size());
  std::vector<Margin> margins(faces.size());
  std::vector<char> stable(faces.size());
  double total_angle = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    solid_angles[f] = FaceSolidAngle(faces[f], centre);
    total_angle += solid_angles[f];
    margins[f] = StabilityMargin(faces[f], centre);
    stable[f] = margins[f].distance_mm > min_margin;
  }
  std::vector<int> tipped_onto(faces.size(), kUnresolved);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!stable[f]) tipped_onto[f] = FaceTippedOnto(faces, static_cast<int>(f), margins[f].side);
  }
  const std::vector<int> rests_on = RestingFaces(faces, stable, tipped_onto);
  std::vector<double> drained(faces.size(), 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (rests_on[f] >= 0) drained[rests_on[f]] += solid_angles[f];
  }
  std::vector<RestingPose> poses;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (!stable[f]) continue;
    const HullFace& face = faces[f];
    RestingPose pose;
    pose.up_in_model = -face.outward_normal;
    pose.probability = drained[f] / total_angle;
    pose.stability_margin_mm = margins[f].distance_mm;
    pose.height_mm = face.plane_offset - face.outward_normal.dot(centre);
    pose.axis_name = AxisName(pose.up_in_model);
    poses.push_back(std::move(pose));
  }
  SortMostLikelyFirst(poses);
  return GroupNearbyPoses(poses);
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
