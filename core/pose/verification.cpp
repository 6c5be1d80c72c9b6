// SPDX-License-Identifier: MIT
#include "pose/verification.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

#include "features/quantize.h"
#include "render/rasterizer.h"
#include "util/error.h"

namespace layermod {
namespace {

// Every kPixelStep-th pixel of every kPixelStep-th row is judged: the measures are shares of
// hundreds to thousands of silhouette pixels, and rendering and reading a quarter of them costs
// a quarter. Pixel (x, y) of the sparse render (PinholeCamera::EveryNthPixel) is pixel
// (kPixelStep * x, kPixelStep * y) of the capture.
constexpr int kPixelStep = 2;

// The capture's pixel under pixel (x, y) of the sparse render's region `roi`.
cv::Point CapturePixel(const cv::Rect& roi, int x, int y) {
  return {kPixelStep * (x + roi.x), kPixelStep * (y + roi.y)};
}

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
      const float scene = depth_mm.at<float>(CapturePixel(view.roi, x, y));
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

constexpr int kRingPx = 2;  // width of the ring outside the silhouette, in sparse pixels

// The view's mask and depth pasted into `area` (a rectangle of the image containing view.roi).
void PasteView(const RenderedView& view, const cv::Rect& area, cv::Mat& mask, cv::Mat& depth) {
  mask = cv::Mat::zeros(area.size(), CV_8U);
  depth = cv::Mat::zeros(area.size(), CV_32F);
  const cv::Rect inside(view.roi.tl() - area.tl(), view.roi.size());
  view.mask.copyTo(mask(inside));
  view.depth_mm.copyTo(depth(inside), view.mask);
}

double SurfaceContinuation(const RenderedView& view, const cv::Mat& depth_mm, double tolerance_mm) {
  const cv::Rect image(0, 0, (depth_mm.cols + kPixelStep - 1) / kPixelStep,
                       (depth_mm.rows + kPixelStep - 1) / kPixelStep);
  const cv::Rect area = cv::Rect(view.roi.x - kRingPx, view.roi.y - kRingPx,
                                 view.roi.width + 2 * kRingPx, view.roi.height + 2 * kRingPx) &
                        image;
  cv::Mat mask, depth;
  PasteView(view, area, mask, depth);
  const cv::Mat kernel =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * kRingPx + 1, 2 * kRingPx + 1));
  cv::Mat grown, nearby_depth;
  cv::dilate(mask, grown, kernel);
  cv::dilate(depth, nearby_depth, kernel);  // the farthest model depth within the ring's width
  int judged = 0;
  int continued = 0;
  for (int y = 0; y < area.height; ++y) {
    for (int x = 0; x < area.width; ++x) {
      if (grown.at<std::uint8_t>(y, x) == 0 || mask.at<std::uint8_t>(y, x) != 0) continue;
      const float scene = depth_mm.at<float>(CapturePixel(area, x, y));
      if (scene <= 0.0f) continue;
      ++judged;
      if (std::abs(scene - nearby_depth.at<float>(y, x)) <= tolerance_mm) ++continued;
    }
  }
  return judged > 0 ? static_cast<double>(continued) / judged : 0.0;
}

double HueDistanceDeg(int a, int b) {  // OpenCV hue is 0..179 for 0..358 degrees
  const int difference = std::abs(a - b) % 180;
  return 2.0 * std::min(difference, 180 - difference);
}

// Whether the scene lies in front of the model at sparse pixel (x, y): an occluder, whose colour
// and edges are not the part's. Never without depth.
bool HiddenByScene(const RenderedView& view, const cv::Mat& depth_mm, int x, int y,
                   double tolerance_mm) {
  if (depth_mm.empty()) return false;
  const float scene = depth_mm.at<float>(CapturePixel(view.roi, x, y));
  return scene > 0.0f && scene < view.depth_mm.at<float>(y, x) - tolerance_mm;
}

// Over the silhouette's saturated pixels the scene does not hide.
double ColorAgreement(const RenderedView& view, const cv::Mat& color_bgr, const cv::Mat& depth_mm,
                      const VerificationOptions& options) {
  if (color_bgr.empty()) return 1.0;
  cv::Mat scene_bgr(view.roi.size(), CV_8UC3);
  for (int y = 0; y < scene_bgr.rows; ++y) {
    for (int x = 0; x < scene_bgr.cols; ++x) {
      scene_bgr.at<cv::Vec3b>(y, x) = color_bgr.at<cv::Vec3b>(CapturePixel(view.roi, x, y));
    }
  }
  cv::Mat model_hsv, scene_hsv;
  cv::cvtColor(view.color, model_hsv, cv::COLOR_BGR2HSV);
  cv::cvtColor(scene_bgr, scene_hsv, cv::COLOR_BGR2HSV);
  int judged = 0;
  int agreeing = 0;
  for (int y = 0; y < view.mask.rows; ++y) {
    for (int x = 0; x < view.mask.cols; ++x) {
      if (view.mask.at<std::uint8_t>(y, x) == 0) continue;
      const cv::Vec3b model = model_hsv.at<cv::Vec3b>(y, x);
      if (model[1] < 80 || model[2] < 40) continue;  // hue is meaningless on grey/dark pixels
      if (HiddenByScene(view, depth_mm, x, y, options.depth_tolerance_mm)) continue;
      ++judged;
      const cv::Vec3b scene = scene_hsv.at<cv::Vec3b>(y, x);
      if (HueDistanceDeg(model[0], scene[0]) <= options.hue_tolerance_deg) ++agreeing;
    }
  }
  // Fewer than 5 % saturated pixels: the part is texture-less grey, colour says nothing.
  if (judged < std::max(20, cv::countNonZero(view.mask) / 20)) return 1.0;
  return static_cast<double>(agreeing) / judged;
}

// Gradient label (GradientOrientationLabel: the scene labels' bins) of the outline's normal at
// sparse pixel (x, y): the direction across which the smoothed mask changes; -1 where it is flat.
int OutlineLabel(const cv::Mat& smooth_mask, int x, int y) {
  const auto at = [&](int u, int v) {
    u = std::clamp(u, 0, smooth_mask.cols - 1);
    v = std::clamp(v, 0, smooth_mask.rows - 1);
    return static_cast<double>(smooth_mask.at<float>(v, u));
  };
  const double gx = at(x + 1, y - 1) + 2.0 * at(x + 1, y) + at(x + 1, y + 1) - at(x - 1, y - 1) -
                    2.0 * at(x - 1, y) - at(x - 1, y + 1);
  const double gy = at(x - 1, y + 1) + 2.0 * at(x, y + 1) + at(x + 1, y + 1) - at(x - 1, y - 1) -
                    2.0 * at(x, y - 1) - at(x + 1, y - 1);
  if (gx == 0.0 && gy == 0.0) return -1;
  return GradientOrientationLabel(static_cast<float>(gx), static_cast<float>(gy));
}

bool IsOutline(const cv::Mat& mask, int x, int y) {
  if (mask.at<std::uint8_t>(y, x) == 0) return false;
  const auto outside = [&](int u, int v) {
    return u < 0 || v < 0 || u >= mask.cols || v >= mask.rows || mask.at<std::uint8_t>(v, u) == 0;
  };
  return outside(x - 1, y) || outside(x + 1, y) || outside(x, y - 1) || outside(x, y + 1);
}

// Whether the scene has a gradient of `label` (or a neighbouring bin) within kOutlineReachPx of
// capture pixel `pixel`; nullopt when the labels do not cover that neighbourhood.
constexpr int kOutlineReachPx = 1;
std::optional<bool> SceneEdgeNear(const GradientLabels& gradients, cv::Point pixel, int label) {
  const cv::Point at = pixel - gradients.offset;
  const cv::Rect reach(at.x - kOutlineReachPx, at.y - kOutlineReachPx, 2 * kOutlineReachPx + 1,
                       2 * kOutlineReachPx + 1);
  const cv::Rect labels_rect(0, 0, gradients.labels.cols, gradients.labels.rows);
  if ((reach & labels_rect) != reach) return std::nullopt;
  const auto wanted = static_cast<std::uint8_t>((1u << label) | (1u << ((label + 1) % 8)) |
                                                (1u << ((label + 7) % 8)));
  for (int y = reach.y; y < reach.br().y; ++y) {
    const auto* row = gradients.labels.ptr<std::uint8_t>(y);
    for (int x = reach.x; x < reach.br().x; ++x) {
      if ((row[x] & wanted) != 0) return true;
    }
  }
  return false;
}

// `image`: the capture's size. Where the image's border cuts the silhouette there is no outline.
double OutlineAgreement(const RenderedView& view, const cv::Mat& depth_mm, cv::Size image,
                        const GradientLabels& gradients, double tolerance_mm) {
  if (gradients.labels.empty()) return 0.0;
  const cv::Rect inner(kPixelStep, kPixelStep, image.width - 2 * kPixelStep,
                       image.height - 2 * kPixelStep);
  cv::Mat smooth_mask;
  view.mask.convertTo(smooth_mask, CV_32F);
  cv::GaussianBlur(smooth_mask, smooth_mask, cv::Size(5, 5), 1.0, 1.0, cv::BORDER_CONSTANT);
  int judged = 0;
  int agreeing = 0;
  for (int y = 0; y < view.mask.rows; ++y) {
    for (int x = 0; x < view.mask.cols; ++x) {
      if (!IsOutline(view.mask, x, y)) continue;
      const cv::Point pixel = CapturePixel(view.roi, x, y);
      if (!inner.contains(pixel) || HiddenByScene(view, depth_mm, x, y, tolerance_mm)) continue;
      const int label = OutlineLabel(smooth_mask, x, y);
      if (label < 0) continue;
      const std::optional<bool> near = SceneEdgeNear(gradients, pixel, label);
      if (!near) continue;
      ++judged;
      if (*near) ++agreeing;
    }
  }
  return judged > 0 ? static_cast<double>(agreeing) / judged : 0.0;
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
                        const VerificationOptions& options, const GradientLabels& gradients) {
  options.Validate();
  Verification result;
  const RenderedView view = RenderView(mesh, camera.EveryNthPixel(kPixelStep), pose);
  if (view.empty()) return result;
  const int silhouette = cv::countNonZero(view.mask);
  result.silhouette_px = silhouette * kPixelStep * kPixelStep;
  const bool has_depth = !depth_mm.empty();
  if (has_depth) {
    const DepthCounts counts = CompareDepth(view, depth_mm, options.depth_tolerance_mm);
    const int judged = counts.consistent + counts.contradicted;
    result.depth_inlier_ratio = judged > 0 ? static_cast<double>(counts.consistent) / judged : 0.0;
    result.depth_fit = judged > 0 ? counts.agreement / judged : 0.0;
    result.visible_ratio = static_cast<double>(counts.consistent + counts.occluded) / silhouette;
    const int measured = judged + counts.occluded;
    if (measured > 0) {
      result.occluded_ratio = static_cast<double>(counts.occluded) / measured;
      result.contradicted_ratio = static_cast<double>(counts.contradicted) / measured;
    }
    result.surface_continuation = SurfaceContinuation(view, depth_mm, options.depth_tolerance_mm);
  }
  result.color_agreement = ColorAgreement(view, color_bgr, depth_mm, options);
  result.outline_agreement = OutlineAgreement(view, depth_mm, cv::Size(camera.width, camera.height),
                                              gradients, options.depth_tolerance_mm);
  const bool depth_ok =
      !has_depth || (result.depth_inlier_ratio >= options.min_depth_inlier_ratio &&
                     result.visible_ratio >= options.min_visible_ratio);
  result.accepted = depth_ok && result.color_agreement >= options.min_color_agreement;
  return result;
}

}  // namespace layermod
