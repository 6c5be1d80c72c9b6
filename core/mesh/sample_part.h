// SPDX-License-Identifier: MIT
#pragma once

#include "mesh/model.h"

namespace layermod {

// The bundled sample object: a texture-less steel angle bracket (100 x 60 x 70 mm) with a
// stepped gusset, two holes in the base and one in the upright, placed so that no rotation maps
// the part onto itself (its pose is unique). Closed, outward-oriented, light grey, normals set,
// origin within a millimetre of its circumscribing-sphere centre. Deterministic.
TriMesh MakeSampleBracket();

}  // namespace layermod
