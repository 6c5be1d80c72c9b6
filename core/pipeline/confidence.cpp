// SPDX-License-Identifier: MIT
#include "pipeline/confidence.h"

#include <algorithm>
#include <cmath>

namespace layermod {
namespace {

// Logistic regression: confidence = 1 / (1 + exp(-(bias + sum w_i x_i))), features in the order
// of ConfidenceFeatures::Names(). Fitted by tools/fit_confidence.py on the outcomes of six scene
// sets (docs/RESULTS.md, "Depth normals in each pixel's viewing-ray frame": the N and P sets,
// the 8 LineMOD objects on harder and on tabletop scenes and the bundled bracket): 2308
// detections, 938 right, 1370 wrong (1282 of them of parts the frame does not show).
//
//   tools/fit_confidence.py ev_hardN/report.json ev_hardP/report.json ev_tabN/report.json
//       ev_tabP/report.json ev_brN/report.json ev_brP/report.json   (one command line)
//   tools/fit_confidence.py --no-depth cal_table_rgb_eval/report.json
struct LogisticModel {
  double bias;
  std::array<double, ConfidenceFeatures::kCount> weights;
};

constexpr LogisticModel kWithDepth{-27.0317,
                                   {17.6067, 17.6881, 6.8612, -31.0103, 1.5743, -10.7095, -1.0311,
                                    9.3941, 6.8490, -11.2202, 10.4395}};
// Without depth the distance is only the matched layer's: the confidence is that the detection is
// right in the image (projected box IoU >= 0.5 with the truth), fitted on colour-only runs.
constexpr LogisticModel kWithoutDepth{-12.1041, {9.4217, 0, 0, 0, 0, 0, 0, 2.4283, 0, 0, 0}};

double Evaluate(const LogisticModel& model, const ConfidenceFeatures& features) {
  double z = model.bias;
  for (int i = 0; i < ConfidenceFeatures::kCount; ++i) {
    z += model.weights[static_cast<std::size_t>(i)] * features.values[static_cast<std::size_t>(i)];
  }
  return 1.0 / (1.0 + std::exp(-z));
}

}  // namespace

std::array<std::string_view, ConfidenceFeatures::kCount> ConfidenceFeatures::Names() {
  return {"score",
          "depth_fit",
          "depth_inlier_ratio",
          "visible_ratio",
          "occluded_ratio",
          "contradicted_ratio",
          "surface_continuation",
          "color_agreement",
          "icp_inlier_ratio",
          "icp_rmse",
          "outline_agreement"};
}

ConfidenceFeatures FeaturesOf(const Detection& detection) {
  const Verification& v = detection.verification;
  ConfidenceFeatures features;
  features.values = {detection.score / 100.0,    v.depth_fit,
                     v.depth_inlier_ratio,       v.visible_ratio,
                     v.occluded_ratio,           v.contradicted_ratio,
                     v.surface_continuation,     v.color_agreement,
                     detection.icp.inlier_ratio, std::min(detection.icp.rmse_mm / 10.0, 2.0),
                     v.outline_agreement};
  return features;
}

double DetectionConfidence(const ConfidenceFeatures& features, bool has_depth) {
  return Evaluate(has_depth ? kWithDepth : kWithoutDepth, features);
}

}  // namespace layermod
