// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "mesh/model.h"

namespace layermod {

// CAD exports and scans carry far more triangles than pixels a part covers in a VGA image
// (the LineMOD can: 45k triangles over about 25k pixels at 650 mm), which makes every render
// slow while changing no feature. Simplifies a copy of the mesh by quadric edge collapses
// until at most `max_triangles` remain, never moving the surface by more than `max_error_mm`
// and never flipping a face; remaining vertices keep their colours. A mesh already small
// enough is returned unchanged. Throws Error for max_triangles == 0 or a non-positive error.
TriMesh DecimateMesh(const TriMesh& mesh, std::size_t max_triangles, double max_error_mm);

}  // namespace layermod
