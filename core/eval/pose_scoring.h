// SPDX-License-Identifier: MIT
#pragma once

// One estimated pose judged against the truth with every measure the reports show.

#include "eval/eval_model.h"
#include "eval/pose_metrics.h"
#include "geometry/camera.h"
#include "geometry/pose.h"

namespace layermod {

struct EvalMetricOptions {
  double km = 0.1;                   // correct when ADD(-S) <= km * diameter (Eq. 8)
  double proj2d_threshold_px = 5.0;  // correct in 2D when the projection error is at most this
  double min_box_iou = 0.5;          // detected when the projected boxes overlap this much

  void Validate() const;  // throws Error naming the bad field
};

struct PoseScore {
  double error_mm = 0.0;  // ADD-S for symmetric objects, else ADD
  bool symmetric_metric = false;
  double proj2d_px = 0.0;
  double box_iou = 0.0;  // projected model boxes, estimate vs truth
  bool correct = false;  // error_mm <= km * diameter
  bool proj2d_correct = false;
  bool box_correct = false;  // box_iou >= min_box_iou
};

PoseScore ScorePose(const EvalModel& model, const Pose& estimated, const Pose& truth,
                    const PinholeCamera& camera, const EvalMetricOptions& options);

}  // namespace layermod
