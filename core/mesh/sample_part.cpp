// SPDX-License-Identifier: MIT
#include "mesh/sample_part.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <vector>

#include "geometry/sphere.h"
#include "util/error.h"

namespace layermod {
namespace {

// The part is a union of cells of a rectilinear grid. Every cell face on the surface is a tile
// whose border carries the same 16 points (corners, mid-sides and two more per side), so that
// neighbouring tiles share vertices exactly and the surface is closed without any boolean
// operation. A tile is either a fan around its centre or an annulus around a polygonal hole.
using Cell = std::array<int, 3>;

// Grid lines in mm: x along the base, y across it, z up. Cell x0 is the upright, z0 the base.
const std::array<std::vector<double>, 3> kLines = {{
    {0, 8, 20, 40, 60, 80, 100},
    {0, 20, 40, 50, 60},
    {0, 8, 20, 32, 48, 70},
}};

struct Hole {
  Cell cell;
  int axis;
  double radius_mm;
};
const std::array<Hole, 3> kHoles = {{
    {{4, 0, 0}, 2, 6.5},  // base, near the front edge
    {{5, 1, 0}, 2, 5.0},  // base, far end
    {{0, 1, 3}, 0, 6.0},  // upright, off-centre
}};

constexpr int kRing = 16;  // polygon sides of a hole, border points of a tile
const OpenMesh::Vec3uc kGreyColour(170, 170, 175);

std::set<Cell> SolidCells() {
  std::set<Cell> cells;
  const int nx = static_cast<int>(kLines[0].size()) - 1;
  const int ny = static_cast<int>(kLines[1].size()) - 1;
  const int nz = static_cast<int>(kLines[2].size()) - 1;
  for (int x = 0; x < nx; ++x) {
    for (int y = 0; y < ny; ++y) cells.insert({x, y, 0});  // base plate
  }
  for (int y = 0; y < ny; ++y) {
    for (int z = 1; z < nz; ++z) cells.insert({0, y, z});  // upright
  }
  // Three-step gusset between base and upright, off the middle of the width.
  for (const Cell& cell :
       {Cell{1, 2, 1}, Cell{1, 2, 2}, Cell{1, 2, 3}, Cell{2, 2, 1}, Cell{2, 2, 2}, Cell{3, 2, 1}}) {
    cells.insert(cell);
  }
  return cells;
}

// Position of refined grid index `r` on `axis`: each cell is split at the fractions where the
// 16 directions of the ring (multiples of 22.5 deg) cross a square's sides.
double RefinedCoordinate(int axis, int r) {
  const double t = std::tan(std::numbers::pi / 8.0);
  const std::array<double, 4> fraction = {0.0, 0.5 * (1.0 - t), 0.5, 0.5 * (1.0 + t)};
  const auto& lines = kLines[axis];
  const int cell = r / 4;
  if (cell + 1 >= static_cast<int>(lines.size())) return lines.back();
  return lines[cell] + fraction[r % 4] * (lines[cell + 1] - lines[cell]);
}

// Offsets (0..4 in refined steps) of the 16 border points of a tile, counter-clockwise from +u.
std::array<std::array<int, 2>, kRing> BorderOffsets() {
  std::array<std::array<int, 2>, kRing> offsets{};
  int u = 4, v = 2;
  for (int k = 0; k < kRing; ++k) {
    offsets[k] = {u, v};
    // Walk the square's border: up the right side, left along the top, down, right along the
    // bottom.
    if (u == 4 && v < 4) {
      ++v;
    } else if (v == 4 && u > 0) {
      --u;
    } else if (u == 0 && v > 0) {
      --v;
    } else {
      ++u;
    }
  }
  return offsets;
}

class BracketBuilder {
 public:
  TriMesh Build() {
    const std::set<Cell> solid = SolidCells();
    for (const Cell& cell : solid) {
      for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
          Cell neighbour = cell;
          neighbour[axis] += side == 0 ? -1 : 1;
          if (solid.count(neighbour) == 0) AddTile(cell, axis, side);
        }
      }
    }
    for (int h = 0; h < static_cast<int>(kHoles.size()); ++h) AddHoleWall(h);
    return std::move(mesh_);
  }

 private:
  TriMesh::VertexHandle LatticeVertex(const std::array<int, 3>& r) {
    const std::array<int, 4> key = {-1, r[0], r[1], r[2]};
    const auto found = vertices_.find(key);
    if (found != vertices_.end()) return found->second;
    const TriMesh::Point p(RefinedCoordinate(0, r[0]), RefinedCoordinate(1, r[1]),
                           RefinedCoordinate(2, r[2]));
    return vertices_[key] = mesh_.add_vertex(p);
  }

  // Vertex k of hole `h`'s polygon on its low (side 0) or high (side 1) face.
  TriMesh::VertexHandle RingVertex(int h, int side, int k) {
    const std::array<int, 4> key = {h, side, k, 0};
    const auto found = vertices_.find(key);
    if (found != vertices_.end()) return found->second;
    const Hole& hole = kHoles[h];
    const int u = (hole.axis + 1) % 3, v = (hole.axis + 2) % 3;
    const double angle = 2.0 * std::numbers::pi * k / kRing;
    TriMesh::Point p;
    p[hole.axis] = RefinedCoordinate(hole.axis, 4 * (hole.cell[hole.axis] + side));
    p[u] = RefinedCoordinate(u, 4 * hole.cell[u] + 2) + hole.radius_mm * std::cos(angle);
    p[v] = RefinedCoordinate(v, 4 * hole.cell[v] + 2) + hole.radius_mm * std::sin(angle);
    return vertices_[key] = mesh_.add_vertex(p);
  }

  // `flip` reverses the winding (faces looking along -axis).
  void AddTriangle(TriMesh::VertexHandle a, TriMesh::VertexHandle b, TriMesh::VertexHandle c,
                   bool flip) {
    const auto face = flip ? mesh_.add_face(a, c, b) : mesh_.add_face(a, b, c);
    if (!face.is_valid()) throw Error("sample bracket: construction is not manifold");
  }

  int HoleAt(const Cell& cell, int axis) const {
    for (int h = 0; h < static_cast<int>(kHoles.size()); ++h) {
      if (kHoles[h].cell == cell && kHoles[h].axis == axis) return h;
    }
    return -1;
  }

  void AddTile(const Cell& cell, int axis, int side) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const bool flip = side == 0;  // the low face looks along -axis
    std::array<TriMesh::VertexHandle, kRing> border;
    const auto offsets = BorderOffsets();
    for (int k = 0; k < kRing; ++k) {
      std::array<int, 3> r{};
      r[axis] = 4 * (cell[axis] + side);
      r[u] = 4 * cell[u] + offsets[k][0];
      r[v] = 4 * cell[v] + offsets[k][1];
      border[k] = LatticeVertex(r);
    }
    const int hole = HoleAt(cell, axis);
    for (int k = 0; k < kRing; ++k) {
      const int next = (k + 1) % kRing;
      if (hole < 0) {
        std::array<int, 3> centre{};
        centre[axis] = 4 * (cell[axis] + side);
        centre[u] = 4 * cell[u] + 2;
        centre[v] = 4 * cell[v] + 2;
        AddTriangle(LatticeVertex(centre), border[k], border[next], flip);
      } else {
        const auto inner_k = RingVertex(hole, side, k);
        const auto inner_next = RingVertex(hole, side, next);
        AddTriangle(border[k], border[next], inner_next, flip);
        AddTriangle(border[k], inner_next, inner_k, flip);
      }
    }
  }

  // The hole's inner wall faces its axis: away from the material.
  void AddHoleWall(int h) {
    for (int k = 0; k < kRing; ++k) {
      const int next = (k + 1) % kRing;
      const auto low_k = RingVertex(h, 0, k), low_next = RingVertex(h, 0, next);
      const auto high_k = RingVertex(h, 1, k), high_next = RingVertex(h, 1, next);
      AddTriangle(low_k, high_k, high_next, false);
      AddTriangle(low_k, high_next, low_next, false);
    }
  }

  TriMesh mesh_;
  std::map<std::array<int, 4>, TriMesh::VertexHandle> vertices_;
};

// Whole millimetres keep the coordinates readable in the saved file.
void MoveOriginToCentre(TriMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    points.emplace_back(p[0], p[1], p[2]);
  }
  const Eigen::Vector3d centre = MinimalEnclosingSphere(points).centre;
  const TriMesh::Point shift(std::round(centre.x()), std::round(centre.y()),
                             std::round(centre.z()));
  for (const auto vh : mesh.vertices()) mesh.point(vh) -= shift;
}

}  // namespace

TriMesh MakeSampleBracket() {
  TriMesh mesh = BracketBuilder().Build();
  MoveOriginToCentre(mesh);
  for (const auto vh : mesh.vertices()) mesh.set_color(vh, kGreyColour);
  mesh.update_face_normals();
  mesh.update_vertex_normals();
  return mesh;
}

}  // namespace layermod
