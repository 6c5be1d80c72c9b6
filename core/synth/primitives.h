// SPDX-License-Identifier: MIT
#pragma once

// Meshes built in code for the synthetic scenes' clutter. Each stands on z = 0 in its own
// frame, centred on the z axis, +Z up; one colour (RGB in [0, 1]).

#include <Eigen/Core>

#include "mesh/render_mesh.h"

namespace layermod {

// Closed box of `size_mm` (x, y, z).
RenderMesh MakeBoxMesh(const Eigen::Vector3f& size_mm, const Eigen::Vector3f& color);

// Closed cylinder with `segments` sides (>= 3).
RenderMesh MakeCylinderMesh(float radius_mm, float height_mm, int segments,
                            const Eigen::Vector3f& color);

}  // namespace layermod
