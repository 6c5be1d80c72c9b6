// SPDX-License-Identifier: MIT
#include "templates/template_picture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "features/feature_overlay.h"
#include "render/rasterizer.h"

namespace layermod {
namespace {

constexpr int kFeaturePaddingPx = 6;

// A black "view" around the template's features, for archives whose mesh is not at hand.
RenderedView BlackViewAroundFeatures(const cv::Rect& bbox_px) {
  RenderedView view;
  view.roi =
      cv::Rect(bbox_px.x - kFeaturePaddingPx, bbox_px.y - kFeaturePaddingPx,
               bbox_px.width + 2 * kFeaturePaddingPx, bbox_px.height + 2 * kFeaturePaddingPx);
  view.mask = cv::Mat::zeros(view.roi.size(), CV_8U);
  view.color = cv::Mat::zeros(view.roi.size(), CV_8UC3);
  return view;
}

}  // namespace

cv::Mat RenderTemplatePicture(const TemplateRecord& record, const PinholeCamera& camera,
                              const RenderMesh* mesh) {
  const ExtractedTemplate features{record.bbox_px, record.levels};
  RenderedView view;
  if (mesh != nullptr) view = RenderView(*mesh, camera, record.cam_from_model);
  if (view.roi.area() == 0) {
    if (record.bbox_px.area() == 0) return {};
    view = BlackViewAroundFeatures(record.bbox_px);
  }
  return RenderFeatureOverlay(view, features);
}

cv::Mat FitInSquare(const cv::Mat& image, int size_px) {
  cv::Mat square = cv::Mat::zeros(size_px, size_px, CV_8UC3);
  if (image.empty()) return square;
  const double scale = std::min(static_cast<double>(size_px) / image.cols,
                                static_cast<double>(size_px) / image.rows);
  const int width = std::clamp(static_cast<int>(std::lround(image.cols * scale)), 1, size_px);
  const int height = std::clamp(static_cast<int>(std::lround(image.rows * scale)), 1, size_px);
  cv::Mat scaled;
  cv::resize(image, scaled, cv::Size(width, height), 0, 0,
             scale > 1.0 ? cv::INTER_NEAREST : cv::INTER_AREA);
  scaled.copyTo(square(cv::Rect((size_px - width) / 2, (size_px - height) / 2, width, height)));
  return square;
}

}  // namespace layermod
