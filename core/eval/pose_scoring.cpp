// SPDX-License-Identifier: MIT
#include "eval/pose_scoring.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace layermod {

void EvalMetricOptions::Validate() const {
  if (!(km > 0.0) || !std::isfinite(km)) throw Error("km must be a positive number");
  if (!(proj2d_threshold_px > 0.0) || !std::isfinite(proj2d_threshold_px)) {
    throw Error("the 2D projection threshold must be a positive number of pixels");
  }
  if (!(min_box_iou > 0.0 && min_box_iou <= 1.0)) {
    throw Error("the minimum box IoU must be in (0, 1]");
  }
}

PoseScore ScorePose(const EvalModel& model, const Pose& estimated, const Pose& truth,
                    const PinholeCamera& camera, const EvalMetricOptions& options) {
  PoseScore score;
  score.symmetric_metric = model.symmetric;
  score.error_mm = model.symmetric ? AddSErrorMm(model.points, *model.tree, estimated, truth)
                                   : AddErrorMm(model.points, estimated, truth);
  score.proj2d_px = Projection2DErrorPx(model.points, estimated, truth, camera);
  score.box_iou = BoxIoU(ProjectedBox(model.points, estimated, camera),
                         ProjectedBox(model.points, truth, camera));
  score.correct = score.error_mm <= options.km * model.diameter_mm;
  score.proj2d_correct = score.proj2d_px <= options.proj2d_threshold_px;
  score.box_correct = score.box_iou >= options.min_box_iou;
  return score;
}

}  // namespace layermod
