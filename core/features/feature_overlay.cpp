// SPDX-License-Identifier: MIT
#include "features/feature_overlay.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "features/quantize.h"

namespace layermod {
namespace {

constexpr double kTickLengthPx = 4.0;

// The view's colour, or a grey silhouette when the colour is missing or black.
cv::Mat OverlayBase(const RenderedView& view) {
  const cv::Size size = view.roi.size();
  if (!view.color.empty() && view.color.size() == size && view.color.type() == CV_8UC3) {
    double max_value = 0.0;
    cv::minMaxLoc(view.color.reshape(1), nullptr, &max_value);
    if (max_value > 0.0) return view.color.clone();
  }
  cv::Mat base = cv::Mat::zeros(size, CV_8UC3);
  if (view.mask.size() == size && view.mask.type() == CV_8U) {
    base.setTo(cv::Scalar::all(110), view.mask);
  }
  return base;
}

cv::Point2d Direction(double angle_deg) {
  const double angle_rad = angle_deg * CV_PI / 180.0;
  return {std::cos(angle_rad), std::sin(angle_rad)};
}

// Ticks first, dots second, so that no tick hides a neighbour's dot.
void DrawTick(const Feature& feature, cv::Point at, cv::Mat* image) {
  const cv::Point2d centre(at);
  if (feature.modality == Modality::kColorGradient) {
    const cv::Point2d tick = Direction(GradientLabelAngleDeg(feature.label)) * kTickLengthPx;
    cv::line(*image, centre - tick, centre + tick, cv::Scalar(0, 160, 0), 1, cv::LINE_AA);
  } else {
    const cv::Point2d tick = Direction(NormalLabelAngleDeg(feature.label)) * kTickLengthPx;
    cv::line(*image, centre, centre + tick, cv::Scalar(255, 80, 0), 1, cv::LINE_AA);
  }
}

void DrawDot(const Feature& feature, cv::Point at, cv::Mat* image) {
  const bool color = feature.modality == Modality::kColorGradient;
  image->at<cv::Vec3b>(at) = color ? cv::Vec3b(0, 255, 0) : cv::Vec3b(0, 0, 255);
}

}  // namespace

cv::Mat RenderFeatureOverlay(const RenderedView& view, const ExtractedTemplate& tmpl) {
  cv::Mat overlay = OverlayBase(view);
  if (tmpl.levels.empty()) return overlay;
  // Level-0 features are relative to bbox_px.tl() in camera pixels; the image starts at roi.tl().
  const cv::Point origin = tmpl.bbox_px.tl() - view.roi.tl();
  const cv::Rect inside({}, overlay.size());
  for (const Feature& feature : tmpl.levels[0].features) {
    DrawTick(feature, origin + cv::Point(feature.x, feature.y), &overlay);
  }
  for (const Feature& feature : tmpl.levels[0].features) {
    const cv::Point at = origin + cv::Point(feature.x, feature.y);
    if (inside.contains(at)) DrawDot(feature, at, &overlay);
  }
  return overlay;
}

}  // namespace layermod
