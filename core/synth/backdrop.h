// SPDX-License-Identifier: MIT
#pragma once

// The backdrop of a synthetic scene: textured planar rectangles intersected analytically with
// every pixel's ray. Plane 0 is the table top (world z = 0, its frame the world's), then the
// floor below it and a wall behind the target, so that low views see a room, not a table
// running to the horizon.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <opencv2/core.hpp>
#include <random>
#include <vector>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "synth/textures.h"

namespace layermod {

struct BackdropPlane {
  Pose world_from_plane;          // the plane is z = 0 of this frame, its normal +z
  Eigen::AlignedBox2d extent_mm;  // the rectangle, in plane x, y
  cv::Mat texture;                // BGR8, kTextureSize square
  TextureMapping mapping;         // plane x, y (mm) to texels
};

inline constexpr int kTablePlane = 0;

struct Backdrop {
  std::vector<BackdropPlane> planes;  // planes[kTablePlane] is the table
};

// The table `table_extent` (world xy) textured by a photo of `backgrounds` (procedural when
// empty), a floor 0.7..0.8 m below it and a wall 1..2.5 m behind `target_xy` as seen from
// `camera_in_world`. Throws IoError when a background image cannot be read.
Backdrop MakeBackdrop(const Eigen::AlignedBox2d& table_extent, const Eigen::Vector2d& target_xy,
                      const Eigen::Vector3d& camera_in_world,
                      const std::vector<std::filesystem::path>& backgrounds, std::mt19937_64& rng);

// The nearest backdrop plane through every pixel.
struct BackdropPixels {
  cv::Mat depth_mm;     // CV_32F camera z (mm), 0 where no plane is hit
  cv::Mat plane_index;  // CV_8S index into Backdrop::planes, -1 where none
  cv::Mat plane_xy;     // CV_32FC2 the hit point in its plane's x, y (mm)
};
BackdropPixels IntersectBackdrop(const Backdrop& backdrop, const PinholeCamera& camera,
                                 const Pose& cam_from_world);

// The backdrop's colour at its pixels (BGR8, black elsewhere): each plane's texture times its
// Lambert shading under the light (`light_to_world` unit, towards the light).
cv::Mat ShadeBackdrop(const Backdrop& backdrop, const BackdropPixels& pixels,
                      const Eigen::Vector3d& light_to_world, double ambient);

}  // namespace layermod
