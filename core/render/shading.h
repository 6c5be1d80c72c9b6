// SPDX-License-Identifier: MIT
// Internal to the rasterizer: turns the visibility buffer into depth, mask, normals and colour.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/camera.h"
#include "mesh/render_mesh.h"
#include "render/rasterizer.h"
#include "render/visibility.h"

namespace layermod::render_internal {

// Shades every covered pixel once from its triangle: depth is the exact z where the pixel's ray
// meets the triangle's plane, the normal is the triangle's face normal turned towards the camera,
// the colour is the perspective-correct interpolated vertex colour times Lambert shading.
// The view covers `output`, which contains buffer.window; pixels outside the buffer are zero.
RenderedView ShadeVisibility(const RenderMesh& mesh, const ScratchVector<Eigen::Vector3f>& in_cam,
                             const VisibilityBuffer& buffer, const PinholeCamera& camera,
                             const RenderOptions& options, const PixelWindow& output);

// A view of `window` with every pixel zero (nothing visible).
RenderedView BlankView(const PixelWindow& window);

}  // namespace layermod::render_internal
