// SPDX-License-Identifier: MIT
// Hand-built rendered views with exact geometry, so feature tests do not depend on the rasterizer.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "render/rasterizer.h"
#include "support/test_cameras.h"

namespace layermod::test {

// Depth (mm) of the plane through `point_mm` with normal `normal` seen through each camera pixel
// of `roi` (exact ray-plane intersection).
cv::Mat PlaneDepth(const PinholeCamera& camera, const cv::Rect& roi,
                   const Eigen::Vector3d& point_mm, const Eigen::Vector3d& normal);

// A square pyramid pointing at the camera, centred on camera pixel `centre_px`: base half-size
// `half_px`, base depth `base_mm`, apex `height_mm` nearer. Every face is an exact 3D plane
// (inverse depth affine in pixels) with its own colour; background black, depth 0, mask 0.
RenderedView PyramidView(const cv::Rect& roi, cv::Point centre_px, int half_px, float base_mm,
                         float height_mm);

// A flat disc of radius `radius_px` (camera pixels) at constant depth, grey, centred on
// `centre_px`.
RenderedView DiscView(const cv::Rect& roi, cv::Point2d centre_px, double radius_px, float depth_mm);

}  // namespace layermod::test
