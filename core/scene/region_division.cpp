// SPDX-License-Identifier: MIT
#include "scene/region_division.h"

#include <tbb/parallel_for.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

// Breadth-first growth from `seed` over valid cells while the depth spread stays within
// `spread_mm`. Marks grown cells with `stamp` in `visited` and returns them.
std::vector<int> GrowRegion(const cv::Mat& cell_depth, int seed, double spread_mm, int stamp,
                            std::vector<int>& visited) {
  const int width = cell_depth.cols;
  const int total = static_cast<int>(cell_depth.total());
  const float* depth = cell_depth.ptr<float>();
  std::vector<int> region{seed};
  visited[static_cast<std::size_t>(seed)] = stamp;
  float lowest = depth[seed];
  float highest = depth[seed];
  for (std::size_t head = 0; head < region.size(); ++head) {
    const int cell = region[head];
    const int x = cell % width;
    const int neighbours[4] = {x > 0 ? cell - 1 : -1, x + 1 < width ? cell + 1 : -1, cell - width,
                               cell + width};
    for (int next : neighbours) {
      if (next < 0 || next >= total || visited[static_cast<std::size_t>(next)] == stamp) continue;
      const float z = depth[next];
      if (z <= 0.0f) continue;
      const float new_low = std::min(lowest, z);
      const float new_high = std::max(highest, z);
      if (new_high - new_low > spread_mm) continue;
      lowest = new_low;
      highest = new_high;
      visited[static_cast<std::size_t>(next)] = stamp;
      region.push_back(next);
    }
  }
  return region;
}

int NearestLayer(double depth_mm, const std::vector<double>& layers) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(layers.size()); ++i) {
    if (std::abs(layers[static_cast<std::size_t>(i)] - depth_mm) <
        std::abs(layers[static_cast<std::size_t>(best)] - depth_mm)) {
      best = i;
    }
  }
  return best;
}

void SplitIntoBlocks(const cv::Mat& layer_cells, int layer_index, double layer_depth_mm,
                     const RegionDivisionOptions& options, const cv::Size& image_size,
                     std::vector<SceneBlock>& blocks) {
  cv::Mat labels, stats, centroids;
  const int count =
      cv::connectedComponentsWithStats(layer_cells, labels, stats, centroids, 8, CV_32S);
  const int cell = options.cell_size_px;
  for (int label = 1; label < count; ++label) {
    const int area = stats.at<int>(label, cv::CC_STAT_AREA);
    if (area < options.min_block_cells) continue;
    SceneBlock block;
    block.layer_index = layer_index;
    block.layer_depth_mm = layer_depth_mm;
    block.cells = (labels == label);
    block.cell_count = area;
    const cv::Rect cells(
        stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
        stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
    block.bbox_px =
        cv::Rect(cells.x * cell, cells.y * cell, cells.width * cell, cells.height * cell) &
        cv::Rect(cv::Point(0, 0), image_size);
    blocks.push_back(std::move(block));
  }
}

}  // namespace

void RegionDivisionOptions::Validate() const {
  if (cell_size_px < 1 || cell_size_px > 64) throw Error("region division: cell size 1..64 px");
  if (seed_step_cells < 1) throw Error("region division: seed step must be positive");
  if (!(depth_spread_mm >= 0.0) || !(max_layer_distance_mm >= 0.0)) {
    throw Error("region division: depth spread and layer distance must be >= 0");
  }
  if (min_block_cells < 1) throw Error("region division: min_block_cells must be positive");
}

bool RegionDivision::BlockContains(const SceneBlock& block, cv::Point pixel) const {
  if (pixel.x < 0 || pixel.y < 0 || pixel.x >= image_size.width || pixel.y >= image_size.height) {
    return false;
  }
  return block.cells.at<std::uint8_t>(pixel.y / cell_size_px, pixel.x / cell_size_px) != 0;
}

cv::Mat CellMedianDepth(const cv::Mat& depth_mm, int cell) {
  if (depth_mm.type() != CV_32F) throw Error("region division: depth must be CV_32F mm");
  if (cell < 1) throw Error("region division: cell size must be positive");
  const cv::Size cells((depth_mm.cols + cell - 1) / cell, (depth_mm.rows + cell - 1) / cell);
  cv::Mat result(cells, CV_32F, cv::Scalar(0));
  // Cells of 4 px and more are sampled on a 2-px lattice: a quarter of the work for a median
  // that summarises the same surface.
  const int stride = cell >= 4 ? 2 : 1;
  tbb::parallel_for(0, cells.height, [&](int cy) {
    std::vector<float> values;
    values.reserve(static_cast<std::size_t>(cell) * static_cast<std::size_t>(cell));
    for (int cx = 0; cx < cells.width; ++cx) {
      values.clear();
      const int y_end = std::min(depth_mm.rows, (cy + 1) * cell);
      const int x_end = std::min(depth_mm.cols, (cx + 1) * cell);
      int sampled = 0;
      for (int y = cy * cell; y < y_end; y += stride) {
        const float* row = depth_mm.ptr<float>(y);
        for (int x = cx * cell; x < x_end; x += stride) {
          ++sampled;
          if (row[x] > 0.0f) values.push_back(row[x]);
        }
      }
      // A cell needs a majority of valid samples to carry a depth.
      if (values.size() * 2 < static_cast<std::size_t>(sampled)) continue;
      auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
      std::nth_element(values.begin(), middle, values.end());
      result.at<float>(cy, cx) = *middle;
    }
  });
  return result;
}

RegionDivision DivideScene(const cv::Mat& depth_mm, const std::vector<double>& layer_depths_mm,
                           double radius_mm, const RegionDivisionOptions& options) {
  options.Validate();
  return DivideScene(CellMedianDepth(depth_mm, options.cell_size_px), depth_mm.size(),
                     layer_depths_mm, radius_mm, options);
}

RegionDivision DivideScene(const cv::Mat& cell_depth_mm, const cv::Size& image_size,
                           const std::vector<double>& layer_depths_mm, double radius_mm,
                           const RegionDivisionOptions& options) {
  options.Validate();
  const cv::Size expected_cells(
      (image_size.width + options.cell_size_px - 1) / options.cell_size_px,
      (image_size.height + options.cell_size_px - 1) / options.cell_size_px);
  if (cell_depth_mm.type() != CV_32F || cell_depth_mm.size() != expected_cells) {
    throw Error("region division: cell depth must be CV_32F, one value per cell of the image");
  }
  if (layer_depths_mm.empty()) throw Error("region division: no depth layers");
  if (!(radius_mm > 0.0)) throw Error("region division: sphere radius must be positive");
  const double spread = options.depth_spread_mm > 0 ? options.depth_spread_mm : radius_mm;
  const double max_distance =
      options.max_layer_distance_mm > 0 ? options.max_layer_distance_mm : radius_mm;

  RegionDivision division;
  division.image_size = image_size;
  division.cell_size_px = options.cell_size_px;
  division.cell_depth_mm = cell_depth_mm;
  const cv::Mat& cell_depth = division.cell_depth_mm;
  std::vector<cv::Mat> layer_cells(layer_depths_mm.size());
  for (cv::Mat& cells : layer_cells) cells = cv::Mat::zeros(cell_depth.size(), CV_8U);

  std::vector<int> visited(cell_depth.total(), -1);
  int stamp = 0;
  const int step = options.seed_step_cells;
  for (int y = step / 2; y < cell_depth.rows; y += step) {
    for (int x = step / 2; x < cell_depth.cols; x += step) {
      const float seed_depth = cell_depth.at<float>(y, x);
      if (seed_depth <= 0.0f) continue;
      // A seed already inside a region of its own nearest layer would grow a near-duplicate
      // region: the paper merges such overlaps anyway, so skip the work.
      const auto seed_layer = static_cast<std::size_t>(NearestLayer(seed_depth, layer_depths_mm));
      if (layer_cells[seed_layer].at<std::uint8_t>(y, x) != 0) continue;
      const std::vector<int> region =
          GrowRegion(cell_depth, y * cell_depth.cols + x, spread, stamp++, visited);
      double sum = 0.0;
      for (int cell : region) sum += cell_depth.ptr<float>()[cell];
      const double mean = sum / static_cast<double>(region.size());
      const int layer = NearestLayer(mean, layer_depths_mm);
      if (std::abs(layer_depths_mm[static_cast<std::size_t>(layer)] - mean) > max_distance) {
        continue;
      }
      std::uint8_t* cells = layer_cells[static_cast<std::size_t>(layer)].ptr<std::uint8_t>();
      for (int cell : region) cells[cell] = 255;
    }
  }
  for (std::size_t layer = 0; layer < layer_cells.size(); ++layer) {
    SplitIntoBlocks(layer_cells[layer], static_cast<int>(layer), layer_depths_mm[layer], options,
                    division.image_size, division.blocks);
  }
  return division;
}

}  // namespace layermod
