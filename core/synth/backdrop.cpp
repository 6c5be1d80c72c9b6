// SPDX-License-Identifier: MIT
#include "synth/backdrop.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "synth/random_draws.h"

namespace layermod {
namespace {

constexpr double kRoomHalfSizeMm = 8000.0;
constexpr double kWallHeightMm = 2500.0;

BackdropPlane Floor(std::mt19937_64& rng) {
  BackdropPlane floor;
  floor.world_from_plane.t = Eigen::Vector3d(0.0, 0.0, -Uniform(rng, 700.0, 800.0));
  floor.extent_mm = Eigen::AlignedBox2d(Eigen::Vector2d::Constant(-kRoomHalfSizeMm),
                                        Eigen::Vector2d::Constant(kRoomHalfSizeMm));
  floor.texture = MakeProceduralTexture(SurfaceKind::kFloor, rng);
  floor.mapping = RandomTextureMapping(600.0, 1500.0, rng);
  return floor;
}

// A vertical wall facing the camera, behind the target.
BackdropPlane Wall(const Eigen::Vector2d& target_xy, const Eigen::Vector3d& camera_in_world,
                   double floor_z, std::mt19937_64& rng) {
  Eigen::Vector2d towards_camera = camera_in_world.head<2>() - target_xy;
  towards_camera =
      towards_camera.norm() > 1e-6 ? towards_camera.normalized() : Eigen::Vector2d::UnitX();
  const double turn = DegToRad(Uniform(rng, -30.0, 30.0));
  const Eigen::Vector2d normal = Eigen::Rotation2Dd(turn) * towards_camera;
  const Eigen::Vector2d origin = target_xy - Uniform(rng, 1000.0, 2500.0) * normal;
  BackdropPlane wall;
  // Plane x: horizontal along the wall; plane y: world up; plane z: the normal.
  wall.world_from_plane.R.col(0) = Eigen::Vector3d(-normal.y(), normal.x(), 0.0);
  wall.world_from_plane.R.col(1) = Eigen::Vector3d::UnitZ();
  wall.world_from_plane.R.col(2) = Eigen::Vector3d(normal.x(), normal.y(), 0.0);
  wall.world_from_plane.t = Eigen::Vector3d(origin.x(), origin.y(), 0.0);
  wall.extent_mm = Eigen::AlignedBox2d(Eigen::Vector2d(-kRoomHalfSizeMm, floor_z),
                                       Eigen::Vector2d(kRoomHalfSizeMm, kWallHeightMm));
  wall.texture = MakeProceduralTexture(SurfaceKind::kWall, rng);
  wall.mapping = RandomTextureMapping(800.0, 2000.0, rng);
  return wall;
}

}  // namespace

Backdrop MakeBackdrop(const Eigen::AlignedBox2d& table_extent, const Eigen::Vector2d& target_xy,
                      const Eigen::Vector3d& camera_in_world,
                      const std::vector<std::filesystem::path>& backgrounds, std::mt19937_64& rng) {
  Backdrop backdrop;
  BackdropPlane table;
  table.extent_mm = table_extent;
  table.texture = MakeTableTexture(backgrounds, rng);
  // A photo spans about what a camera at 1 m sees; procedural tops tile at any scale.
  table.mapping = RandomTextureMapping(450.0, 900.0, rng);
  backdrop.planes.push_back(std::move(table));
  backdrop.planes.push_back(Floor(rng));
  const double floor_z = backdrop.planes.back().world_from_plane.t.z();
  backdrop.planes.push_back(Wall(target_xy, camera_in_world, floor_z, rng));
  return backdrop;
}

BackdropPixels IntersectBackdrop(const Backdrop& backdrop, const PinholeCamera& camera,
                                 const Pose& cam_from_world) {
  BackdropPixels pixels;
  pixels.depth_mm = cv::Mat::zeros(camera.height, camera.width, CV_32F);
  pixels.plane_index = cv::Mat(camera.height, camera.width, CV_8S, cv::Scalar(-1));
  pixels.plane_xy = cv::Mat::zeros(camera.height, camera.width, CV_32FC2);
  // Each plane in camera coordinates: the ray x = z * (u', v', 1) meets n . x = d at z = d / n.r.
  std::vector<Pose> plane_from_cam;
  for (const BackdropPlane& plane : backdrop.planes) {
    plane_from_cam.push_back((cam_from_world * plane.world_from_plane).Inverse());
  }
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const Eigen::Vector3d ray((x - camera.cx) / camera.fx, (y - camera.cy) / camera.fy, 1.0);
      double nearest = std::numeric_limits<double>::max();
      for (std::size_t i = 0; i < backdrop.planes.size(); ++i) {
        // In plane coordinates the ray is o + z * r; it meets z_plane = 0 at z = -o.z / r.z.
        const Eigen::Vector3d direction = plane_from_cam[i].R * ray;
        const Eigen::Vector3d& origin = plane_from_cam[i].t;
        if (std::abs(direction.z()) < 1e-12) continue;
        const double depth = -origin.z() / direction.z();
        if (depth <= 0.0 || depth >= nearest) continue;
        const Eigen::Vector2d hit = (origin + depth * direction).head<2>();
        if (!backdrop.planes[i].extent_mm.contains(hit)) continue;
        nearest = depth;
        pixels.depth_mm.at<float>(y, x) = static_cast<float>(depth);
        pixels.plane_index.at<schar>(y, x) = static_cast<schar>(i);
        pixels.plane_xy.at<cv::Vec2f>(y, x) =
            cv::Vec2f(static_cast<float>(hit.x()), static_cast<float>(hit.y()));
      }
    }
  }
  return pixels;
}

cv::Mat ShadeBackdrop(const Backdrop& backdrop, const BackdropPixels& pixels,
                      const Eigen::Vector3d& light_to_world, double ambient) {
  cv::Mat color = cv::Mat::zeros(pixels.depth_mm.size(), CV_8UC3);
  for (std::size_t i = 0; i < backdrop.planes.size(); ++i) {
    const BackdropPlane& plane = backdrop.planes[i];
    const cv::Mat mask = pixels.plane_index == static_cast<int>(i);
    if (cv::countNonZero(mask) == 0) continue;
    const Eigen::Vector3d normal = plane.world_from_plane.R.col(2);
    const double shade = ambient + (1.0 - ambient) * std::max(0.0, normal.dot(light_to_world));
    cv::Mat sampled = SampleTexture(plane.texture, pixels.plane_xy, mask, plane.mapping);
    sampled.convertTo(sampled, CV_8UC3, shade);
    sampled.copyTo(color, mask);
  }
  return color;
}

}  // namespace layermod
