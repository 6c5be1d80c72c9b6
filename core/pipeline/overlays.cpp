// SPDX-License-Identifier: MIT
#include "pipeline/overlays.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

#include "render/rasterizer.h"

namespace layermod {
namespace {

// `origin` is the text's bottom-left; the text is moved inside the image where it would leave it
// (a part at the image's border).
void DrawLabel(cv::Mat& canvas, const std::string& text, cv::Point origin,
               const cv::Scalar& color) {
  constexpr double kScale = 0.45;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, kScale, 3, &baseline);
  origin.x = std::clamp(origin.x, 0, std::max(0, canvas.cols - size.width));
  origin.y = std::clamp(origin.y, size.height, std::max(size.height, canvas.rows - baseline));
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, kScale, cv::Scalar(0, 0, 0), 3,
              cv::LINE_AA);
  cv::putText(canvas, text, origin, cv::FONT_HERSHEY_SIMPLEX, kScale, color, 1, cv::LINE_AA);
}

cv::Mat BlockPixelMask(const RegionDivision& division, const SceneBlock& block) {
  cv::Mat mask;
  cv::resize(
      block.cells, mask,
      cv::Size(block.cells.cols * division.cell_size_px, block.cells.rows * division.cell_size_px),
      0, 0, cv::INTER_NEAREST);
  return mask(cv::Rect(cv::Point(0, 0), division.image_size));
}

void DrawAxes(cv::Mat& canvas, const Pose& pose, const Eigen::Vector3d& centre, double length_mm,
              const PinholeCamera& camera) {
  const Eigen::Vector2d origin = camera.Project(pose * centre);
  const cv::Scalar colors[3] = {{0, 0, 255}, {0, 255, 0}, {255, 0, 0}};
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector2d tip =
        camera.Project(pose * (centre + length_mm * Eigen::Vector3d::Unit(axis)));
    cv::line(canvas, cv::Point2d(origin.x(), origin.y()), cv::Point2d(tip.x(), tip.y()),
             colors[axis], 2, cv::LINE_AA);
  }
}

// Legend lines: the first text baseline 16 px below the legend's top, one line every 18 px.
constexpr int kLegendFirstBaselinePx = 16;
constexpr int kLegendLinePx = 18;
constexpr int kLegendDescentPx = 8;  // below a line's baseline, room for its descenders

}  // namespace

void DimColor(cv::Mat& canvas) { canvas.convertTo(canvas, -1, 0.6, 0.0); }

cv::Scalar LayerColor(int index, int count) {
  cv::Mat hsv(1, 1, CV_8UC3,
              cv::Scalar(static_cast<double>(150 * index) / std::max(1, count - 1), 220, 255));
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  const cv::Vec3b pixel = bgr.at<cv::Vec3b>(0, 0);
  return cv::Scalar(pixel[0], pixel[1], pixel[2]);
}

void DrawRegionDivision(cv::Mat& canvas, const ObjectDiagnostics& diagnostics,
                        const ArchiveObject& object) {
  const RegionDivision& division = diagnostics.division;
  const int layers = static_cast<int>(object.layer_depths_mm.size());
  for (const SceneBlock& block : division.blocks) {
    const cv::Mat mask = BlockPixelMask(division, block);
    cv::Mat tint(canvas.size(), CV_8UC3, LayerColor(block.layer_index, layers));
    cv::Mat blended;
    cv::addWeighted(canvas, 0.45, tint, 0.55, 0.0, blended);
    blended.copyTo(canvas, mask);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    cv::drawContours(canvas, contours, -1, cv::Scalar(255, 255, 255), 1);
  }
}

int DrawLayerLegend(cv::Mat& canvas, const ArchiveObject& object, int top_px) {
  const int layers = static_cast<int>(object.layer_depths_mm.size());
  for (int i = 0; i < layers; ++i) {
    const cv::Point corner(8, top_px + kLegendFirstBaselinePx + kLegendLinePx * i);
    cv::rectangle(canvas, corner + cv::Point(0, -10), corner + cv::Point(12, 2),
                  LayerColor(i, layers), cv::FILLED);
    char text[48];
    std::snprintf(text, sizeof(text), "layer %d: %.0f mm", i,
                  object.layer_depths_mm[static_cast<std::size_t>(i)]);
    DrawLabel(canvas, text, corner + cv::Point(18, 0), cv::Scalar(255, 255, 255));
  }
  return top_px + kLegendFirstBaselinePx + kLegendLinePx * (layers - 1) + kLegendDescentPx;
}

void DrawCoarsePositioning(cv::Mat& canvas, const ObjectDiagnostics& diagnostics) {
  const CoarsePositioning& coarse = diagnostics.coarse;
  for (int index : coarse.kept) {
    const BlockCandidates& block = coarse.evaluated[static_cast<std::size_t>(index)];
    const SceneBlock& scene_block =
        diagnostics.division.blocks[static_cast<std::size_t>(block.block_index)];
    cv::rectangle(canvas, scene_block.bbox_px, cv::Scalar(0, 255, 255), 2);
  }
  for (const BlockCandidates& block : coarse.evaluated) {
    for (const DetectionPoint& point : block.points) {
      if (!point.kept) cv::circle(canvas, point.pixel, 1, cv::Scalar(0, 0, 200), cv::FILLED);
    }
  }
  for (const DetectionPoint& point : coarse.KeptPoints()) {
    cv::circle(canvas, point.pixel, 3, cv::Scalar(0, 255, 0), cv::FILLED);
  }
}

int DrawCoarseLegend(cv::Mat& canvas, int top_px) {
  DrawLabel(canvas, "kept points: green, rejected: red, kept blocks: yellow",
            {8, top_px + kLegendFirstBaselinePx}, cv::Scalar(255, 255, 255));
  return top_px + kLegendFirstBaselinePx + kLegendDescentPx;
}

void DrawMatches(cv::Mat& canvas, const ObjectDiagnostics& diagnostics,
                 const TemplateArchive& archive) {
  int drawn = 0;
  for (const RawMatch& match : diagnostics.matches) {
    const TemplateRecord& tmpl = archive.templates().at(match.template_id);
    const cv::Rect box(match.x, match.y, tmpl.bbox_px.width, tmpl.bbox_px.height);
    const cv::Scalar colour = drawn == 0 ? cv::Scalar(0, 255, 0) : cv::Scalar(0, 200, 255);
    cv::rectangle(canvas, box, colour, drawn == 0 ? 2 : 1);
    for (const Feature& feature : tmpl.levels.at(0).features) {
      const cv::Scalar dot = feature.modality == Modality::kColorGradient ? cv::Scalar(0, 255, 0)
                                                                          : cv::Scalar(255, 80, 80);
      if (drawn == 0) {
        cv::circle(canvas, box.tl() + cv::Point(feature.x, feature.y), 1, dot, cv::FILLED);
      }
    }
    char text[48];
    std::snprintf(text, sizeof(text), "#%u %.1f%%", match.template_id, match.similarity_percent);
    DrawLabel(canvas, text, box.tl() + cv::Point(2, -4), colour);
    if (++drawn == 10) break;
  }
}

void DrawPoses(cv::Mat& canvas, const std::vector<Detection>& detections, const Detector& detector,
               const PinholeCamera& camera) {
  for (const Detection& detection : detections) {
    const ArchiveObject& object = detector.Object(detection.obj_id);
    const RenderedView view = RenderView(object.mesh, camera, detection.cam_from_model);
    if (!view.empty()) {
      std::vector<std::vector<cv::Point>> contours;
      cv::findContours(view.mask.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE,
                       view.roi.tl());
      cv::drawContours(canvas, contours, -1, cv::Scalar(0, 255, 0), 2, cv::LINE_AA);
    }
    DrawAxes(canvas, detection.cam_from_model, object.sphere.centre, object.sphere.radius_mm * 0.8,
             camera);
    char text[96];
    std::snprintf(text, sizeof(text), "%s %.1f%% conf %.2f", detection.name.c_str(),
                  detection.score, detection.confidence);
    const Eigen::Vector2d label_at =
        camera.Project(detection.cam_from_model * object.sphere.centre);
    DrawLabel(canvas, text, cv::Point2d(label_at.x(), label_at.y()) + cv::Point2d(8, -8),
              cv::Scalar(0, 255, 0));
  }
}

}  // namespace layermod
