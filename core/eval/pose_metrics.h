// SPDX-License-Identifier: MIT
#pragma once

// Pose error measures of the paper's §4 (Eqs. 6-8) and BOP's 2D measures. Model points are in
// model mm; poses are cam_from_model.

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "eval/point_search.h"
#include "geometry/camera.h"
#include "geometry/pose.h"

namespace layermod {

// ADD (Eq. 6): mean distance between each model point under the estimated and the true pose (mm).
// Throws Error for an empty point set.
double AddErrorMm(const std::vector<Eigen::Vector3d>& model_points, const Pose& estimated,
                  const Pose& truth);

// ADD-S (Eq. 7): mean, over the model points under the true pose, of the distance to the closest
// model point under the estimated pose (mm). `model_tree` holds the same model points; the query
// is moved into the estimate's model frame, so the tree is built once per object.
double AddSErrorMm(const std::vector<Eigen::Vector3d>& model_points, const PointKdTree& model_tree,
                   const Pose& estimated, const Pose& truth);

// Mean distance between the projections of the model points under both poses (px); infinity when
// a point lies at or behind the camera plane under either pose (such an estimate is unusable).
double Projection2DErrorPx(const std::vector<Eigen::Vector3d>& model_points, const Pose& estimated,
                           const Pose& truth, const PinholeCamera& camera);

// Axis-aligned box of the projected model points (px, unclipped; x/y floor, far side ceil); empty
// when a point lies at or behind the camera plane.
cv::Rect ProjectedBox(const std::vector<Eigen::Vector3d>& model_points, const Pose& pose,
                      const PinholeCamera& camera);

// Intersection over union of two boxes; 0 when both are empty.
double BoxIoU(const cv::Rect& a, const cv::Rect& b);

}  // namespace layermod
