// SPDX-License-Identifier: MIT
#include "scene/coarse_positioning.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "util/error.h"

namespace layermod {
namespace {

int CountInWindow(const cv::Mat& integral, cv::Point centre, int size_px) {
  const int half = size_px / 2;
  const int x0 = std::clamp(centre.x - half, 0, integral.cols - 1);
  const int y0 = std::clamp(centre.y - half, 0, integral.rows - 1);
  const int x1 = std::clamp(centre.x - half + size_px, 0, integral.cols - 1);
  const int y1 = std::clamp(centre.y - half + size_px, 0, integral.rows - 1);
  return integral.at<int>(y1, x1) - integral.at<int>(y0, x1) - integral.at<int>(y1, x0) +
         integral.at<int>(y0, x0);
}

// Depth at a detection point: the pixel, else its cell's median (sensor holes are common).
float PointDepth(const RegionDivision& division, const cv::Mat& depth_mm, cv::Point pixel) {
  const float depth = depth_mm.at<float>(pixel);
  if (depth > 0.0f) return depth;
  return division.cell_depth_mm.at<float>(pixel.y / division.cell_size_px,
                                          pixel.x / division.cell_size_px);
}

BlockCandidates EvaluateBlock(const RegionDivision& division, int block_index,
                              const cv::Mat& depth_mm, const cv::Mat& integral, double focal_px,
                              double diameter_mm, const LayerEdgeRange& range,
                              const CoarsePositioningOptions& options) {
  const SceneBlock& block = division.blocks[static_cast<std::size_t>(block_index)];
  BlockCandidates candidates;
  candidates.block_index = block_index;
  const int step = options.point_step_px;
  const cv::Rect box = block.bbox_px;
  for (int y = box.y + step / 2; y < box.br().y; y += step) {
    for (int x = box.x + step / 2; x < box.br().x; x += step) {
      if (!division.BlockContains(block, {x, y})) continue;
      DetectionPoint point;
      point.pixel = {x, y};
      point.depth_mm = PointDepth(division, depth_mm, point.pixel);
      if (point.depth_mm <= 0.0f) continue;
      const int object_size_px =
          std::max(1, static_cast<int>(std::lround(focal_px * diameter_mm / point.depth_mm)));
      const int raw = CountInWindow(integral, point.pixel, object_size_px);
      point.edge_count = static_cast<float>(raw * point.depth_mm / block.layer_depth_mm);
      point.kept = point.edge_count >= options.lower_factor * static_cast<float>(range.n_min) &&
                   point.edge_count <= options.upper_factor * static_cast<float>(range.n_max);
      candidates.kept_count += point.kept ? 1 : 0;
      candidates.points.push_back(point);
    }
  }
  return candidates;
}

}  // namespace

void CoarsePositioningOptions::Validate() const {
  if (point_step_px < 1) throw Error("coarse positioning: point step must be positive");
  if (!(lower_factor >= 0.0f) || !(upper_factor >= lower_factor)) {
    throw Error("coarse positioning: need 0 <= lower factor <= upper factor");
  }
  if (max_blocks < 0) throw Error("coarse positioning: max_blocks must be >= 0 (0 = all)");
  if (hole_fill_px < 0) throw Error("coarse positioning: hole_fill_px must be >= 0");
}

std::vector<DetectionPoint> CoarsePositioning::KeptPoints() const {
  std::vector<DetectionPoint> points;
  for (int index : kept) {
    for (const DetectionPoint& point : evaluated[static_cast<std::size_t>(index)].points) {
      if (point.kept) points.push_back(point);
    }
  }
  return points;
}

CoarsePositioning PositionCoarsely(const RegionDivision& division, const cv::Mat& depth_mm,
                                   const cv::Mat& edge_mask, double focal_px, double diameter_mm,
                                   const std::vector<LayerEdgeRange>& edge_ranges,
                                   const CoarsePositioningOptions& options) {
  options.Validate();
  if (depth_mm.type() != CV_32F || edge_mask.type() != CV_8U ||
      depth_mm.size() != division.image_size || edge_mask.size() != division.image_size) {
    throw Error("coarse positioning: depth (CV_32F) and edge mask (CV_8U) must match the scene");
  }
  if (!(focal_px > 0.0) || !(diameter_mm > 0.0)) {
    throw Error("coarse positioning: focal length and diameter must be positive");
  }
  cv::Mat integral;
  cv::integral(edge_mask / 255, integral, CV_32S);
  CoarsePositioning result;
  for (int i = 0; i < static_cast<int>(division.blocks.size()); ++i) {
    const auto layer =
        static_cast<std::size_t>(division.blocks[static_cast<std::size_t>(i)].layer_index);
    if (layer >= edge_ranges.size() || !edge_ranges[layer].valid) continue;
    result.evaluated.push_back(EvaluateBlock(division, i, depth_mm, integral, focal_px, diameter_mm,
                                             edge_ranges[layer], options));
  }
  std::vector<int> order(result.evaluated.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return result.evaluated[static_cast<std::size_t>(a)].kept_count >
           result.evaluated[static_cast<std::size_t>(b)].kept_count;
  });
  for (int index : order) {
    if (result.evaluated[static_cast<std::size_t>(index)].kept_count == 0) break;
    if (options.max_blocks > 0 && static_cast<int>(result.kept.size()) == options.max_blocks) break;
    result.kept.push_back(index);
  }
  return result;
}

}  // namespace layermod
