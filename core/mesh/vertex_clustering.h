// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "mesh/render_mesh.h"

namespace layermod {

// Vertex clustering (Rossignac & Borrel 1993): vertices in one cube of `cell_mm` merge into
// their mean (position and colour); triangles whose corners merge collapse and are dropped, as
// are repeated ones. Fast and coarse: meant for renders whose pixels are larger than a cell,
// such as pose refinement and verification at working distance. Winding is kept.
RenderMesh ClusterVertices(const RenderMesh& mesh, double cell_mm);

// The mesh clustered with the finest cell (growing by 25 % from `min_cell_mm`) that leaves at most
// `max_triangles`; the mesh itself when it already has no more.
RenderMesh SimplifyToTriangleCount(const RenderMesh& mesh, std::size_t max_triangles,
                                   double min_cell_mm);

}  // namespace layermod
