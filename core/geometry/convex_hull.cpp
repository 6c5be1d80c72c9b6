// SPDX-License-Identifier: MIT
#include "geometry/convex_hull.h"

#include <Eigen/Geometry>
#include <cmath>

#include "util/error.h"

namespace layermod {
namespace {

// A point is above a plane only when it is farther than this fraction of the coordinates' size:
// points closer than that are on the plane as far as rounding can tell, and treating them as above
// would add sliver triangles with ill-defined normals.
constexpr double kRelativePlaneTolerance = 1e-9;

struct Face {
  std::array<int, 3> corners{};    // point indices, counter-clockwise seen from outside
  std::array<int, 3> neighbour{};  // neighbour[i] lies across the edge corners[i] -> corners[i + 1]
  Eigen::Vector3d normal;          // outward, unit
  double offset = 0.0;             // normal . x on the plane
  int first_outside = -1;          // points above this face not on the hull yet (see next_outside_)
  bool alive = true;
};

// An edge of the region the new point sees, as the visible face winds it.
struct HorizonEdge {
  int from = 0;
  int to = 0;
  int hidden_face = 0;  // the face across the edge, which stays
};

// Quickhull (Barber, Dobkin, Huhdanpaa 1996): a tetrahedron grows by its farthest outside point
// until no point is outside; each point is tested only against the faces it could still see.
// Outside sets are linked lists threaded through one array and the horizon bookkeeping lives in
// per-point arrays: a hull of 50k points on a sphere makes 150k faces, and allocating per face
// or per step would cost more than the geometry.
class QuickHull {
 public:
  QuickHull(const std::vector<Eigen::Vector3d>& points, double tolerance)
      : points_(points),
        tolerance_(tolerance),
        next_outside_(points.size(), -1),
        edge_from_(points.size(), -1) {}

  ConvexHull Build() {
    if (!BuildTetrahedron()) return {};
    while (!pending_.empty()) {
      const int face = pending_.back();
      pending_.pop_back();
      if (faces_[face].alive && faces_[face].first_outside >= 0) AddFarthestPoint(face);
    }
    return Result();
  }

 private:
  double Height(const Face& face, int point) const {
    return face.normal.dot(points_[point]) - face.offset;
  }

  int AddFace(int a, int b, int c) {
    Face face;
    face.corners = {a, b, c};
    face.neighbour = {-1, -1, -1};
    const Eigen::Vector3d& pa = points_[a];
    face.normal = (points_[b] - pa).cross(points_[c] - pa).normalized();
    face.offset = face.normal.dot(pa + points_[b] + points_[c]) / 3.0;
    faces_.push_back(face);
    return static_cast<int>(faces_.size()) - 1;
  }

  // The point farthest by `distance`, or -1 when none is beyond the tolerance.
  template <typename Distance>
  int FarthestFrom(const Distance& distance) const {
    int best = -1;
    double best_distance = tolerance_;
    for (int i = 0; i < static_cast<int>(points_.size()); ++i) {
      const double d = distance(i);
      if (d > best_distance) {
        best_distance = d;
        best = i;
      }
    }
    return best;
  }

  bool BuildTetrahedron();
  void LinkTetrahedron();
  void AssignOutside(const std::vector<int>& points, const std::vector<int>& faces);
  int TakeFarthestOutside(Face& face);
  void AddFarthestPoint(int face);
  std::vector<int> VisibleFaces(int eye, int first_face, std::vector<HorizonEdge>& horizon);
  bool IsOneLoop(const std::vector<HorizonEdge>& horizon);
  std::vector<int> AddCone(int eye, const std::vector<HorizonEdge>& horizon);
  ConvexHull Result() const;

  const std::vector<Eigen::Vector3d>& points_;
  const double tolerance_;
  std::vector<Face> faces_;
  std::vector<int> pending_;       // faces that may have outside points
  std::vector<int> next_outside_;  // per point: the next point of the same outside set, or -1
  std::vector<int> edge_from_;     // per point: the horizon edge (or cone face) starting there
  std::vector<int> visit_mark_;    // per face: the eye that last tested it
  std::vector<char> seen_by_eye_;  // per face: whether that eye sees it
};

// The starting tetrahedron spans the points as widely as four of them can: a thin one would leave
// many points within rounding of its faces.
bool QuickHull::BuildTetrahedron() {
  const Eigen::Vector3d& p0 = points_[0];
  const int a = FarthestFrom([&](int i) { return (points_[i] - p0).norm(); });
  if (a < 0) return false;
  const int b = FarthestFrom([&](int i) { return (points_[i] - points_[a]).norm(); });
  if (b < 0) return false;
  const Eigen::Vector3d ab = (points_[b] - points_[a]).normalized();
  const int c = FarthestFrom([&](int i) { return (points_[i] - points_[a]).cross(ab).norm(); });
  if (c < 0) return false;
  const Eigen::Vector3d normal = ab.cross(points_[c] - points_[a]).normalized();
  const int d = FarthestFrom([&](int i) { return std::abs(normal.dot(points_[i] - points_[a])); });
  if (d < 0) return false;
  const std::array<int, 4> corners = {a, b, c, d};
  for (int opposite = 0; opposite < 4; ++opposite) {
    std::array<int, 3> face{};
    for (int k = 0, n = 0; k < 4; ++k) {
      if (k != opposite) face[n++] = corners[k];
    }
    const int index = AddFace(face[0], face[1], face[2]);
    if (Height(faces_[index], corners[opposite]) > 0.0) {
      faces_.pop_back();
      AddFace(face[0], face[2], face[1]);
    }
  }
  LinkTetrahedron();
  std::vector<int> rest;
  for (int i = 0; i < static_cast<int>(points_.size()); ++i) {
    if (i != a && i != b && i != c && i != d) rest.push_back(i);
  }
  AssignOutside(rest, {0, 1, 2, 3});
  return true;
}

void QuickHull::LinkTetrahedron() {
  for (Face& face : faces_) {
    for (int i = 0; i < 3; ++i) {
      const int from = face.corners[i];
      const int to = face.corners[(i + 1) % 3];
      for (int other = 0; other < 4; ++other) {
        const auto& c = faces_[other].corners;
        for (int j = 0; j < 3; ++j) {
          if (c[j] == to && c[(j + 1) % 3] == from) face.neighbour[i] = other;
        }
      }
    }
  }
}

// Each point goes to the face it is highest above; a point above none is inside and dropped.
void QuickHull::AssignOutside(const std::vector<int>& points, const std::vector<int>& faces) {
  for (int point : points) {
    int best = -1;
    double best_height = tolerance_;
    for (int face : faces) {
      const double height = Height(faces_[face], point);
      if (height > best_height) {
        best_height = height;
        best = face;
      }
    }
    if (best < 0) continue;
    next_outside_[point] = faces_[best].first_outside;
    faces_[best].first_outside = point;
  }
  for (int face : faces) {
    if (faces_[face].first_outside >= 0) pending_.push_back(face);
  }
}

int QuickHull::TakeFarthestOutside(Face& face) {
  int before_best = -1;
  int best = face.first_outside;
  for (int before = best, p = next_outside_[best]; p >= 0; before = p, p = next_outside_[p]) {
    if (Height(face, p) > Height(face, best)) {
      best = p;
      before_best = before;
    }
  }
  if (before_best < 0) {
    face.first_outside = next_outside_[best];
  } else {
    next_outside_[before_best] = next_outside_[best];
  }
  return best;
}

void QuickHull::AddFarthestPoint(int face) {
  const int eye = TakeFarthestOutside(faces_[face]);
  std::vector<HorizonEdge> horizon;
  const std::vector<int> visible = VisibleFaces(eye, face, horizon);
  if (!IsOneLoop(horizon)) {
    // The eye is within rounding of several planes, so that the region it sees has holes.
    // Leaving it out moves the hull by no more than that rounding.
    pending_.push_back(face);
    return;
  }
  std::vector<int> orphans;
  for (int f : visible) {
    faces_[f].alive = false;
    for (int p = faces_[f].first_outside; p >= 0; p = next_outside_[p]) orphans.push_back(p);
    faces_[f].first_outside = -1;
  }
  AssignOutside(orphans, AddCone(eye, horizon));
}

// The faces the eye sees, grown from one it sees: they are replaced by a cone from the eye to the
// border of that region (the horizon).
std::vector<int> QuickHull::VisibleFaces(int eye, int first_face,
                                         std::vector<HorizonEdge>& horizon) {
  visit_mark_.resize(faces_.size(), -1);
  seen_by_eye_.resize(faces_.size(), 0);
  std::vector<int> visible = {first_face};
  visit_mark_[first_face] = eye;
  seen_by_eye_[first_face] = 1;
  for (std::size_t k = 0; k < visible.size(); ++k) {
    const Face& face = faces_[visible[k]];
    for (int i = 0; i < 3; ++i) {
      const int next = face.neighbour[i];
      if (visit_mark_[next] != eye) {
        visit_mark_[next] = eye;
        seen_by_eye_[next] = Height(faces_[next], eye) > tolerance_ ? 1 : 0;
        if (seen_by_eye_[next]) visible.push_back(next);
      }
      if (!seen_by_eye_[next]) {
        horizon.push_back({face.corners[i], face.corners[(i + 1) % 3], next});
      }
    }
  }
  return visible;
}

// Whether the horizon is one closed loop: every corner starts exactly one edge, and the walk
// from the first edge comes back to it after visiting all.
bool QuickHull::IsOneLoop(const std::vector<HorizonEdge>& horizon) {
  if (horizon.size() < 3) return false;
  bool one_loop = true;
  for (int e = 0; e < static_cast<int>(horizon.size()); ++e) {
    int& slot = edge_from_[horizon[e].from];
    one_loop = one_loop && slot < 0;
    slot = e;
  }
  if (one_loop) {
    int e = 0;
    std::size_t steps = 0;
    do {
      e = edge_from_[horizon[e].to];
      ++steps;
    } while (e > 0 && steps < horizon.size());
    one_loop = e == 0 && steps == horizon.size();
  }
  for (const HorizonEdge& edge : horizon) edge_from_[edge.from] = -1;
  return one_loop;
}

// One new face per horizon edge, from the edge to the eye, linked to its hidden neighbour and to
// the new faces on either side.
std::vector<int> QuickHull::AddCone(int eye, const std::vector<HorizonEdge>& horizon) {
  std::vector<int> cone;
  for (const HorizonEdge& edge : horizon) {
    const int face = AddFace(edge.from, edge.to, eye);
    faces_[face].neighbour[0] = edge.hidden_face;
    Face& hidden = faces_[edge.hidden_face];
    for (int i = 0; i < 3; ++i) {
      if (hidden.corners[i] == edge.to && hidden.corners[(i + 1) % 3] == edge.from) {
        hidden.neighbour[i] = face;
      }
    }
    edge_from_[edge.from] = face;
    cone.push_back(face);
  }
  for (int face : cone) {
    const int next = edge_from_[faces_[face].corners[1]];
    faces_[face].neighbour[1] = next;  // across to -> eye
    faces_[next].neighbour[2] = face;  // whose eye -> from is the same edge
  }
  for (const HorizonEdge& edge : horizon) edge_from_[edge.from] = -1;
  return cone;
}

ConvexHull QuickHull::Result() const {
  ConvexHull hull;
  std::vector<int> vertex_of(points_.size(), -1);
  for (const Face& face : faces_) {
    if (!face.alive) continue;
    std::array<int, 3> triangle{};
    for (int i = 0; i < 3; ++i) {
      int& vertex = vertex_of[face.corners[i]];
      if (vertex < 0) {
        vertex = static_cast<int>(hull.vertices.size());
        hull.vertices.push_back(points_[face.corners[i]]);
      }
      triangle[i] = vertex;
    }
    hull.triangles.push_back(triangle);
  }
  return hull;
}

}  // namespace

ConvexHull ComputeConvexHull(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 4) return {};
  Eigen::Vector3d low = points[0];
  Eigen::Vector3d high = points[0];
  for (const Eigen::Vector3d& p : points) {
    if (!p.allFinite()) throw Error("convex hull: a point has a non-finite coordinate");
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // Rounding grows with the coordinates' magnitude, not with the spread of the points (as in
  // qhull).
  const double magnitude = low.cwiseAbs().cwiseMax(high.cwiseAbs()).sum();
  return QuickHull(points, kRelativePlaneTolerance * magnitude).Build();
}

Eigen::Vector3d HullVolumeCentroid(const ConvexHull& hull) {
  if (hull.Empty()) throw Error("convex hull: an empty hull has no centroid");
  Eigen::Vector3d inside = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : hull.vertices) inside += v;
  inside /= static_cast<double>(hull.vertices.size());
  // Tetrahedra from a point inside to every triangle fill the hull exactly once.
  double volume = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (const auto& [a, b, c] : hull.triangles) {
    const Eigen::Vector3d& pa = hull.vertices[a];
    const Eigen::Vector3d& pb = hull.vertices[b];
    const Eigen::Vector3d& pc = hull.vertices[c];
    const double tetra = (pa - inside).dot((pb - inside).cross(pc - inside)) / 6.0;
    volume += tetra;
    moment += tetra * (inside + pa + pb + pc) / 4.0;
  }
  return moment / volume;
}

}  // namespace layermod
