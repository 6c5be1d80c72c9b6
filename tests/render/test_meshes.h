// SPDX-License-Identifier: MIT
// Synthetic meshes for the rasterizer tests and benchmark, with their analytic ray intersections.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "mesh/render_mesh.h"
#include "support/test_cameras.h"

namespace layermod::test {

// Icosahedron subdivided `levels` times, vertices on the sphere (20 * 4^levels triangles).
RenderMesh MakeIcosphere(double radius_mm, int levels,
                         const Eigen::Vector3f& color = Eigen::Vector3f::Ones());

// Latitude/longitude sphere: 2 * slices * (stacks - 1) triangles.
RenderMesh MakeUvSphere(double radius_mm, int slices, int stacks,
                        const Eigen::Vector3f& color = Eigen::Vector3f::Ones());

// Axis-aligned box centred on the origin, each face split into cells x cells quads.
RenderMesh MakeBox(const Eigen::Vector3d& half_size_mm, int cells,
                   const Eigen::Vector3f& color = Eigen::Vector3f::Ones());

// Square in the model's z = 0 plane, side `size_mm`, split into cells x cells quads; vertex
// colours red = (x / size + 0.5), green = (y / size + 0.5), blue = 1 (linear over the square).
RenderMesh MakeGradientSquare(double size_mm, int cells);

// Direction (z = 1) of the ray through the centre of pixel (x, y).
Eigen::Vector3d PixelRay(const PinholeCamera& camera, int x, int y);

// An analytic surface hit along a pixel ray: z in the camera frame and the unit normal facing
// the camera; `face` identifies the face for piecewise-planar shapes (else 0).
struct AnalyticHit {
  double depth_mm = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  int face = 0;
};

// First intersection of the ray (direction `ray`, from the camera centre) with a sphere given in
// the camera frame.
std::optional<AnalyticHit> IntersectSphere(const Eigen::Vector3d& ray,
                                           const Eigen::Vector3d& centre_in_cam, double radius_mm);

// First intersection with the axis-aligned model box seen at `cam_from_model`.
std::optional<AnalyticHit> IntersectBox(const Eigen::Vector3d& ray, const Pose& cam_from_model,
                                        const Eigen::Vector3d& half_size_mm);

// A pose looking at the model origin from `distance_mm`, rotated by the given angles.
Pose LookAtPose(double distance_mm, double rx_deg, double ry_deg, double rz_deg,
                const Eigen::Vector2d& offset_mm = Eigen::Vector2d::Zero());

}  // namespace layermod::test
