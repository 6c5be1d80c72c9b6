// SPDX-License-Identifier: MIT
#pragma once

#include <gmock/gmock.h>

#include <Eigen/Core>

namespace layermod::test {

// Matches an Eigen matrix/vector within an absolute tolerance per coefficient.
MATCHER_P2(MatrixNear, expected, tolerance, "") {
  if (arg.rows() != expected.rows() || arg.cols() != expected.cols()) return false;
  const double error = (arg - expected).cwiseAbs().maxCoeff();
  *result_listener << "max abs difference " << error;
  return error <= tolerance;
}

// Matches a Pose: rotation within `rotation_tol` (matrix coefficients), translation in mm.
MATCHER_P3(PoseNear, expected, rotation_tol, translation_mm, "") {
  const double rotation_error = (arg.R - expected.R).cwiseAbs().maxCoeff();
  const double translation_error = (arg.t - expected.t).norm();
  *result_listener << "rotation diff " << rotation_error << ", translation diff "
                   << translation_error << " mm";
  return rotation_error <= rotation_tol && translation_error <= translation_mm;
}

}  // namespace layermod::test
