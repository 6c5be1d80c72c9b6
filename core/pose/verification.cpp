// SPDX-License-Identifier: MIT
#include "pose/verification.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

#include "render/rasterizer.h"
#include "util/error.h"

namespace layermod {
namespace {

struct DepthCounts {
  int consistent = 0;
  int occluded = 0;
  int contradicted = 0;
  double agreement = 0.0;  // sum of max(0, 1 - |difference| / tolerance) over the judged pixels
};

DepthCounts CompareDepth(const RenderedView& view, const cv::Mat& depth_mm, double tolerance_mm) {
  DepthCounts counts;
  for (int y = 0; y < view.mask.rows; ++y) {
    for (int x = 0; x < view.mask.cols; ++x) {
      if (view.mask.at<std::uint8_t>(y, x) == 0) continue;
      const float scene = depth_mm.at<float>(y + view.roi.y, x + view.roi.x);
      if (scene <= 0.0f) continue;  // no measurement: no evidence either way
      const double difference = scene - view.depth_mm.at<float>(y, x);
      if (std::abs(difference) <= tolerance_mm) {
        ++counts.consistent;
        counts.agreement += 1.0 - std::abs(difference) / tolerance_mm;
      } else if (difference < 0) {
        ++counts.occluded;
      } else {
        ++counts.contradicted;
      }
    }
  }
  return counts;
}

double HueDistanceDeg(int a, int b) {  // OpenCV hue is 0..179 for 0..358 degrees
  const int difference = std::abs(a - b) % 180;
  return 2.0 * std::min(difference, 180 - difference);
}

double ColorAgreement(const RenderedView& view, const cv::Mat& color_bgr, double tolerance_deg) {
  if (color_bgr.empty()) return 1.0;
  cv::Mat model_hsv, scene_hsv;
  cv::cvtColor(view.color, model_hsv, cv::COLOR_BGR2HSV);
  cv::cvtColor(color_bgr(view.roi), scene_hsv, cv::COLOR_BGR2HSV);
  int judged = 0;
  int agreeing = 0;
  for (int y = 0; y < view.mask.rows; ++y) {
    for (int x = 0; x < view.mask.cols; ++x) {
      if (view.mask.at<std::uint8_t>(y, x) == 0) continue;
      const cv::Vec3b model = model_hsv.at<cv::Vec3b>(y, x);
      if (model[1] < 80 || model[2] < 40) continue;  // hue is meaningless on grey/dark pixels
      ++judged;
      const cv::Vec3b scene = scene_hsv.at<cv::Vec3b>(y, x);
      if (HueDistanceDeg(model[0], scene[0]) <= tolerance_deg) ++agreeing;
    }
  }
  // Fewer than 5 % saturated pixels: the part is texture-less grey, colour says nothing.
  if (judged < std::max(20, cv::countNonZero(view.mask) / 20)) return 1.0;
  return static_cast<double>(agreeing) / judged;
}

}  // namespace

void VerificationOptions::Validate() const {
  if (!(depth_tolerance_mm > 0.0) || !(hue_tolerance_deg > 0.0)) {
    throw Error("verification: tolerances must be positive");
  }
  for (double ratio : {min_depth_inlier_ratio, min_visible_ratio, min_color_agreement}) {
    if (!(ratio >= 0.0 && ratio <= 1.0)) throw Error("verification: ratios must lie in 0..1");
  }
}

Verification VerifyPose(const RenderMesh& mesh, const PinholeCamera& camera, const Pose& pose,
                        const cv::Mat& depth_mm, const cv::Mat& color_bgr,
                        const VerificationOptions& options) {
  options.Validate();
  Verification result;
  const RenderedView view = RenderView(mesh, camera, pose);
  if (view.empty()) return result;
  result.silhouette_px = cv::countNonZero(view.mask);
  const bool has_depth = !depth_mm.empty();
  if (has_depth) {
    const DepthCounts counts = CompareDepth(view, depth_mm, options.depth_tolerance_mm);
    const int judged = counts.consistent + counts.contradicted;
    result.depth_inlier_ratio = judged > 0 ? static_cast<double>(counts.consistent) / judged : 0.0;
    result.depth_fit = judged > 0 ? counts.agreement / judged : 0.0;
    result.visible_ratio =
        static_cast<double>(counts.consistent + counts.occluded) / result.silhouette_px;
  }
  result.color_agreement = ColorAgreement(view, color_bgr, options.hue_tolerance_deg);
  const bool depth_ok =
      !has_depth || (result.depth_inlier_ratio >= options.min_depth_inlier_ratio &&
                     result.visible_ratio >= options.min_visible_ratio);
  result.accepted = depth_ok && result.color_agreement >= options.min_color_agreement;
  return result;
}

}  // namespace layermod
