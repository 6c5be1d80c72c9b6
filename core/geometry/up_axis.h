// SPDX-License-Identifier: MIT
// The model's reference orientation: which of its axes points up when the part stands as it is
// used. The view envelope (azimuth, elevation above the table, roll) is measured in the upright
// frame, where that axis is +Z; templates still store the true cam_from_model pose, so poses stay
// in the mesh's own frame.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace layermod {

// "+x", "-x", "+y", "-y", "+z", "-z".
const std::vector<std::string>& UpAxisNames();

// The rotation upright_from_model that takes `axis` ("+z", "-y", ...) to +Z. Throws Error for
// other text.
Eigen::Matrix3d UprightFromUpAxis(std::string_view axis);

// The axis name when `upright_from_model` is one of UprightFromUpAxis's rotations.
std::optional<std::string> UpAxisName(const Eigen::Matrix3d& upright_from_model);

// The smallest rotation that turns the model direction `up_in_model` (any length above 0) to +Z:
// the upright frame of a part resting on a tilted face. Throws Error for a zero or non-finite
// vector.
Eigen::Matrix3d UprightFromUpDirection(const Eigen::Vector3d& up_in_model);

// The model direction that points up: upright_from_model^T * +Z.
Eigen::Vector3d UpDirectionInModel(const Eigen::Matrix3d& upright_from_model);

// Throws Error naming `what` unless `rotation` is a proper rotation (orthonormal, det +1, within
// 1e-6).
void ValidateRotation(const Eigen::Matrix3d& rotation, std::string_view what);

}  // namespace layermod
