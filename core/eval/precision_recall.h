// SPDX-License-Identifier: MIT
#pragma once

// Precision and recall of a run's detections over the confidence threshold: each (frame,
// object) pair's first detection is accepted when its confidence reaches the threshold; it is
// right when the object is there and the pose is correct (ADD(-S)), wrong otherwise (a wrong
// pose, or an object the frame does not show).

#include <opencv2/core.hpp>
#include <vector>

#include "eval/eval_runner.h"

namespace layermod {

struct PrecisionRecallPoint {
  double threshold = 0.0;  // accept confidence >= threshold
  double precision = 1.0;  // right over accepted (1 when nothing is accepted)
  double recall = 0.0;     // right over the targets (pairs where the object is there)
};

struct PrecisionRecallCurve {
  std::vector<PrecisionRecallPoint> points;  // thresholds descending, recall ascending
  int targets = 0;
  // The area under the curve with precision made monotone (the best precision at this recall
  // or more), as in PASCAL VOC's average precision; 0..1.
  double area = 0.0;
};

PrecisionRecallCurve ComputePrecisionRecall(const std::vector<TargetOutcome>& outcomes);

// The point at `threshold`: what accepting confidence >= threshold gives.
PrecisionRecallPoint PointAt(const std::vector<TargetOutcome>& outcomes, double threshold);

// A plot of the curve (recall across, precision up) with the operating point at `threshold`
// marked; BGR, about 560 x 440.
cv::Mat DrawPrecisionRecall(const PrecisionRecallCurve& curve, const PrecisionRecallPoint& chosen);

}  // namespace layermod
