// SPDX-License-Identifier: MIT
#pragma once

#include "geometry/resting_poses.h"
#include "mesh/model.h"

namespace layermod {

// The ways the model can lie on a table, most likely first: the up axes to offer for training
// (see geometry/resting_poses.h). In the model's frame, mm.
RestingPoses SuggestRestingPoses(const Model& model);

}  // namespace layermod
