// SPDX-License-Identifier: MIT
#include "render/test_meshes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>

namespace layermod::test {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::uint32_t AddVertex(RenderMesh& mesh, const Eigen::Vector3d& position,
                        const Eigen::Vector3f& color) {
  mesh.positions.push_back(position.cast<float>());
  mesh.colors.push_back(color);
  return static_cast<std::uint32_t>(mesh.positions.size() - 1);
}

// Splits every triangle in four, pushing new vertices onto the sphere.
void SubdivideOnSphere(RenderMesh& mesh, double radius_mm, const Eigen::Vector3f& color) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoints.find(key);
    if (found != midpoints.end()) return found->second;
    const Eigen::Vector3d middle =
        (mesh.positions[a].cast<double>() + mesh.positions[b].cast<double>()).normalized() *
        radius_mm;
    const std::uint32_t index = AddVertex(mesh, middle, color);
    midpoints.emplace(key, index);
    return index;
  };
  std::vector<Triangle> finer;
  for (const Triangle& t : mesh.triangles) {
    const std::uint32_t ab = midpoint(t[0], t[1]);
    const std::uint32_t bc = midpoint(t[1], t[2]);
    const std::uint32_t ca = midpoint(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({t[1], bc, ab});
    finer.push_back({t[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  mesh.triangles = std::move(finer);
}

Eigen::Matrix3d RotationXyz(double rx_deg, double ry_deg, double rz_deg) {
  return (Eigen::AngleAxisd(DegToRad(rz_deg), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(DegToRad(ry_deg), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(DegToRad(rx_deg), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

}  // namespace

RenderMesh MakeIcosphere(double radius_mm, int levels, const Eigen::Vector3f& color) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  const double corners[12][3] = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                                 {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                                 {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  RenderMesh mesh;
  for (const auto& c : corners) {
    AddVertex(mesh, Eigen::Vector3d(c[0], c[1], c[2]).normalized() * radius_mm, color);
  }
  mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < levels; ++level) SubdivideOnSphere(mesh, radius_mm, color);
  return mesh;
}

RenderMesh MakeUvSphere(double radius_mm, int slices, int stacks, const Eigen::Vector3f& color) {
  RenderMesh mesh;
  const std::uint32_t north = AddVertex(mesh, {0, 0, radius_mm}, color);
  for (int i = 1; i < stacks; ++i) {
    const double polar = kPi * i / stacks;
    for (int j = 0; j < slices; ++j) {
      const double azimuth = 2.0 * kPi * j / slices;
      AddVertex(mesh,
                radius_mm * Eigen::Vector3d(std::sin(polar) * std::cos(azimuth),
                                            std::sin(polar) * std::sin(azimuth), std::cos(polar)),
                color);
    }
  }
  const std::uint32_t south = AddVertex(mesh, {0, 0, -radius_mm}, color);
  const auto ring = [&](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * slices + (j % slices));
  };
  for (int j = 0; j < slices; ++j) {
    mesh.triangles.push_back({north, ring(1, j), ring(1, j + 1)});
    mesh.triangles.push_back({south, ring(stacks - 1, j + 1), ring(stacks - 1, j)});
    for (int i = 1; i + 1 < stacks; ++i) {
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      mesh.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  return mesh;
}

RenderMesh MakeBox(const Eigen::Vector3d& half_size_mm, int cells, const Eigen::Vector3f& color) {
  RenderMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    const int u_axis = (axis + 1) % 3;
    const int v_axis = (axis + 2) % 3;
    for (const double side : {-1.0, 1.0}) {
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      for (int i = 0; i <= cells; ++i) {
        for (int j = 0; j <= cells; ++j) {
          Eigen::Vector3d p;
          p[axis] = side * half_size_mm[axis];
          p[u_axis] = (2.0 * i / cells - 1.0) * half_size_mm[u_axis];
          p[v_axis] = (2.0 * j / cells - 1.0) * half_size_mm[v_axis];
          AddVertex(mesh, p, color);
        }
      }
      const auto at = [&](int i, int j) {
        return base + static_cast<std::uint32_t>(i * (cells + 1) + j);
      };
      for (int i = 0; i < cells; ++i) {
        for (int j = 0; j < cells; ++j) {
          mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
          mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
      }
    }
  }
  return mesh;
}

RenderMesh MakeGradientSquare(double size_mm, int cells) {
  RenderMesh mesh;
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j <= cells; ++j) {
      const double x = (static_cast<double>(i) / cells - 0.5) * size_mm;
      const double y = (static_cast<double>(j) / cells - 0.5) * size_mm;
      const Eigen::Vector3f color(static_cast<float>(x / size_mm + 0.5),
                                  static_cast<float>(y / size_mm + 0.5), 1.0f);
      AddVertex(mesh, {x, y, 0.0}, color);
    }
  }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (cells + 1) + j); };
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

Eigen::Vector3d PixelRay(const PinholeCamera& camera, int x, int y) {
  return {(x - camera.cx) / camera.fx, (y - camera.cy) / camera.fy, 1.0};
}

std::optional<AnalyticHit> IntersectSphere(const Eigen::Vector3d& ray,
                                           const Eigen::Vector3d& centre_in_cam, double radius_mm) {
  const double a = ray.squaredNorm();
  const double b = ray.dot(centre_in_cam);
  const double c = centre_in_cam.squaredNorm() - radius_mm * radius_mm;
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  // Nearest intersection in front of the camera (the far one when the camera is inside).
  double s = (b - root) / a;
  if (s <= 0.0) s = (b + root) / a;
  if (s <= 0.0) return std::nullopt;
  AnalyticHit hit;
  hit.depth_mm = s;
  hit.normal = (s * ray - centre_in_cam).normalized();
  if (hit.normal.dot(ray) > 0.0) hit.normal = -hit.normal;
  return hit;
}

std::optional<AnalyticHit> IntersectBox(const Eigen::Vector3d& ray, const Pose& cam_from_model,
                                        const Eigen::Vector3d& half_size_mm) {
  const Eigen::Vector3d origin = -(cam_from_model.R.transpose() * cam_from_model.t);
  const Eigen::Vector3d direction = cam_from_model.R.transpose() * ray;
  double entry = -std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
  int entry_axis = -1;
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (std::abs(origin[axis]) > half_size_mm[axis]) return std::nullopt;
      continue;
    }
    double near = (-half_size_mm[axis] - origin[axis]) / direction[axis];
    double far = (half_size_mm[axis] - origin[axis]) / direction[axis];
    if (near > far) std::swap(near, far);
    if (near > entry) {
      entry = near;
      entry_axis = axis;
    }
    exit = std::min(exit, far);
  }
  if (entry > exit || entry <= 0.0 || entry_axis < 0) return std::nullopt;
  AnalyticHit hit;
  hit.depth_mm = entry;  // the ray's z component is 1
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  normal[entry_axis] = direction[entry_axis] > 0.0 ? -1.0 : 1.0;
  hit.normal = cam_from_model.R * normal;
  hit.face = 2 * entry_axis + (normal[entry_axis] > 0.0 ? 1 : 0);
  return hit;
}

Pose LookAtPose(double distance_mm, double rx_deg, double ry_deg, double rz_deg,
                const Eigen::Vector2d& offset_mm) {
  Pose pose;
  pose.R = RotationXyz(rx_deg, ry_deg, rz_deg);
  pose.t = Eigen::Vector3d(offset_mm.x(), offset_mm.y(), distance_mm);
  return pose;
}

}  // namespace layermod::test
