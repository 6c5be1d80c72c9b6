// SPDX-License-Identifier: MIT
#include "geometry/hull_faces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "geometry/pose.h"

namespace layermod {
namespace {

// Corners within this fraction of the hull's size of a face's plane lie on it. Generous on
// purpose: a side whose triangles tilt by a fraction of kCoplanarAngleDeg (float rounding, a
// scanned base's noise, a slight dome) is one place to rest on, and the angle test alone keeps
// curved sides apart.
constexpr double kRelativePlaneDistance = 1e-2;
// Polygon corners that turn by less than this (times the squared size) are on a straight edge or
// repeat a corner: keeping them would give edges too short to have a reliable direction.
constexpr double kRelativeTurnArea = 1e-12;

struct Triangle {
  Eigen::Vector3d normal;
  double area = 0.0;
};

std::vector<Triangle> Triangles(const ConvexHull& hull) {
  std::vector<Triangle> triangles;
  triangles.reserve(hull.triangles.size());
  for (const auto& [a, b, c] : hull.triangles) {
    const Eigen::Vector3d& pa = hull.vertices[a];
    const Eigen::Vector3d cross = (hull.vertices[b] - pa).cross(hull.vertices[c] - pa);
    triangles.push_back({cross.normalized(), 0.5 * cross.norm()});
  }
  return triangles;
}

// neighbours[t][i]: the triangle across edge i of triangle t (the hull is closed). Found through
// each vertex's triangles: a hull vertex has few, and a hash of 300k edges would be slower.
std::vector<std::array<int, 3>> Neighbours(const ConvexHull& hull) {
  std::vector<int> start(hull.vertices.size() + 1, 0);
  for (const auto& c : hull.triangles) {
    for (int corner : c) ++start[corner + 1];
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<int> fill(start.begin(), start.end() - 1);
  std::vector<int> around(start.back());  // triangles around each vertex, vertex by vertex
  for (int t = 0; t < static_cast<int>(hull.triangles.size()); ++t) {
    for (int corner : hull.triangles[t]) around[fill[corner]++] = t;
  }
  std::vector<std::array<int, 3>> neighbours(hull.triangles.size(), {-1, -1, -1});
  for (std::size_t t = 0; t < hull.triangles.size(); ++t) {
    const auto& c = hull.triangles[t];
    for (int i = 0; i < 3; ++i) {
      const int from = c[i];
      const int to = c[(i + 1) % 3];
      for (int k = start[to]; k < start[to + 1]; ++k) {
        const auto& other = hull.triangles[around[k]];
        for (int j = 0; j < 3; ++j) {
          if (other[j] == to && other[(j + 1) % 3] == from) neighbours[t][i] = around[k];
        }
      }
    }
  }
  return neighbours;
}

double Cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

// Andrew's monotone chain: the convex polygon of `points`, counter-clockwise.
std::vector<Eigen::Vector2d> ConvexPolygon(std::vector<Eigen::Vector2d> points, double min_turn) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  std::vector<Eigen::Vector2d> polygon(2 * points.size());
  std::size_t size = 0;
  const auto add = [&](const Eigen::Vector2d& p, std::size_t floor) {
    while (size >= floor + 2 && Cross2(polygon[size - 2], polygon[size - 1], p) <= min_turn) --size;
    polygon[size++] = p;
  };
  for (const Eigen::Vector2d& p : points) add(p, 0);
  const std::size_t lower = size - 1;
  for (auto p = points.rbegin() + 1; p != points.rend(); ++p) add(*p, lower);
  polygon.resize(size > 1 ? size - 1 : size);  // the last corner repeats the first
  return polygon;
}

// The face through the given triangles: their area-weighted normal, the outermost plane along it
// (the one a table touches) and the convex polygon of their corners on that plane.
HullFace MakeFace(const ConvexHull& hull, const std::vector<Triangle>& triangles,
                  const std::vector<int>& members, double hull_size) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int t : members) normal += triangles[t].area * triangles[t].normal;
  HullFace face;
  face.outward_normal = normal.normalized();
  const Eigen::Vector3d u = face.outward_normal.unitOrthogonal();
  const Eigen::Vector3d v = face.outward_normal.cross(u);  // u x v = normal: counter-clockwise
  std::vector<Eigen::Vector2d> corners;
  face.plane_offset = -std::numeric_limits<double>::infinity();
  for (int t : members) {
    for (int corner : hull.triangles[t]) {
      const Eigen::Vector3d& p = hull.vertices[corner];
      corners.emplace_back(u.dot(p), v.dot(p));
      face.plane_offset = std::max(face.plane_offset, face.outward_normal.dot(p));
    }
  }
  const double min_turn = kRelativeTurnArea * hull_size * hull_size;
  for (const Eigen::Vector2d& q : ConvexPolygon(std::move(corners), min_turn)) {
    face.polygon.push_back(face.plane_offset * face.outward_normal + q.x() * u + q.y() * v);
  }
  return face;
}

double HullSize(const ConvexHull& hull) {
  Eigen::Vector3d low = hull.vertices.front();
  Eigen::Vector3d high = low;
  for (const Eigen::Vector3d& p : hull.vertices) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// The side of the face's polygon nearest to `point`, a point on or near its plane (the distance
// off the plane is the same for every side, so it does not need projecting).
std::size_t NearestSide(const HullFace& face, const Eigen::Vector3d& point) {
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = face.polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = face.polygon[i];
    const Eigen::Vector3d ab = face.polygon[(i + 1) % n] - a;
    const double along = std::clamp(ab.dot(point - a) / ab.squaredNorm(), 0.0, 1.0);
    const double distance = (a + along * ab - point).squaredNorm();
    if (distance < best) {
      best = distance;
      nearest = i;
    }
  }
  return nearest;
}

// Each hull edge between two faces is put on the polygon side nearest to its midpoint: the
// polygon is the hull of the face's corners, so its sides run along the face's border edges.
void FindNeighbours(const ConvexHull& hull, const std::vector<std::array<int, 3>>& neighbours,
                    const std::vector<std::vector<int>>& members, const std::vector<int>& face_of,
                    std::vector<HullFace>& faces) {
  for (std::size_t f = 0; f < faces.size(); ++f) {
    HullFace& face = faces[f];
    face.neighbours.assign(face.polygon.size(), {});
    for (int t : members[f]) {
      const auto& c = hull.triangles[t];
      for (int i = 0; i < 3; ++i) {
        const int across = neighbours[t][i] >= 0 ? face_of[neighbours[t][i]] : -1;
        if (across < 0 || across == static_cast<int>(f)) continue;
        const Eigen::Vector3d middle = 0.5 * (hull.vertices[c[i]] + hull.vertices[c[(i + 1) % 3]]);
        std::vector<int>& side = face.neighbours[NearestSide(face, middle)];
        if (std::find(side.begin(), side.end(), across) == side.end()) side.push_back(across);
      }
    }
  }
}

}  // namespace

std::vector<HullFace> MergeCoplanarTriangles(const ConvexHull& hull) {
  if (hull.Empty()) return {};
  const std::vector<Triangle> triangles = Triangles(hull);
  const std::vector<std::array<int, 3>> neighbours = Neighbours(hull);
  const double hull_size = HullSize(hull);
  const double min_cos = std::cos(DegToRad(kCoplanarAngleDeg));
  const double max_distance = kRelativePlaneDistance * hull_size;
  // Largest triangles first: a face is measured against its most reliable normal, and grows
  // only from it, so a finely tessellated curve cannot chain into one face degree by degree.
  std::vector<int> order(triangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return triangles[a].area > triangles[b].area; });
  std::vector<char> taken(triangles.size(), 0);
  std::vector<HullFace> faces;
  std::vector<std::vector<int>> face_members;
  std::vector<int> face_of(triangles.size(), -1);  // -1: in a face too thin to keep
  for (int seed : order) {
    if (taken[seed]) continue;
    const Eigen::Vector3d& normal = triangles[seed].normal;
    const double offset = normal.dot(hull.vertices[hull.triangles[seed][0]]);
    const auto on_face = [&](int t) {
      if (triangles[t].normal.dot(normal) < min_cos) return false;
      return std::all_of(hull.triangles[t].begin(), hull.triangles[t].end(), [&](int corner) {
        return std::abs(normal.dot(hull.vertices[corner]) - offset) <= max_distance;
      });
    };
    std::vector<int> members = {seed};
    taken[seed] = 1;
    for (std::size_t k = 0; k < members.size(); ++k) {
      for (int next : neighbours[members[k]]) {
        if (next >= 0 && !taken[next] && on_face(next)) {
          taken[next] = 1;
          members.push_back(next);
        }
      }
    }
    HullFace face = MakeFace(hull, triangles, members, hull_size);
    if (face.polygon.size() < 3) continue;
    for (int t : members) face_of[t] = static_cast<int>(faces.size());
    faces.push_back(std::move(face));
    face_members.push_back(std::move(members));
  }
  FindNeighbours(hull, neighbours, face_members, face_of, faces);
  return faces;
}

}  // namespace layermod
