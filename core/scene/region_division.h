// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace layermod {

// Scene region division (paper §3.2, Eq. 1), computed on square cells for speed.
struct RegionDivisionOptions {
  int cell_size_px = 8;     // depth is summarised per cell (median of valid pixels)
  int seed_step_cells = 3;  // seeds on a regular grid of cells
  // A region stops growing when its depth spread would exceed this (paper Eq. 1). 0: the
  // object's sphere radius.
  double depth_spread_mm = 0.0;
  // Regions whose mean depth is farther than this from every layer are dropped (no template can
  // match there). 0: the sphere radius.
  double max_layer_distance_mm = 0.0;
  int min_block_cells = 4;  // smaller connected components are dropped

  void Validate() const;  // throws Error
};

// One connected block W_j attached to a depth layer. Its pixels are the cells set in `cells`.
struct SceneBlock {
  int layer_index = 0;
  double layer_depth_mm = 0.0;
  cv::Mat cells;     // CV_8U, one value per cell, 255 inside the block
  cv::Rect bbox_px;  // bounding box in image pixels (clipped to the image)
  int cell_count = 0;
};

struct RegionDivision {
  cv::Size image_size;
  int cell_size_px = 0;
  cv::Mat cell_depth_mm;  // CV_32F per-cell median depth, 0 where no valid depth
  std::vector<SceneBlock> blocks;

  bool BlockContains(const SceneBlock& block, cv::Point pixel) const;
};

// Divides a depth map (CV_32F mm, 0 = invalid) into blocks of nearly constant depth, each
// attached to the nearest of `layer_depths_mm`. `radius_mm`: the object's sphere radius.
RegionDivision DivideScene(const cv::Mat& depth_mm, const std::vector<double>& layer_depths_mm,
                           double radius_mm, const RegionDivisionOptions& options = {});

// The per-cell median depth DivideScene starts from (CV_32F, 0 where fewer than half the cell's
// samples are valid; cells of 4 px and more are sampled every second pixel in both directions). It
// depends on the depth map and the cell size only, so a frame searched for several objects computes
// it once and divides with the overload below.
cv::Mat CellMedianDepth(const cv::Mat& depth_mm, int cell_size_px);
RegionDivision DivideScene(const cv::Mat& cell_depth_mm, const cv::Size& image_size,
                           const std::vector<double>& layer_depths_mm, double radius_mm,
                           const RegionDivisionOptions& options = {});

}  // namespace layermod
