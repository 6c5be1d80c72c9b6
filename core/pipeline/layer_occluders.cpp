// SPDX-License-Identifier: MIT
#include "pipeline/layer_occluders.h"

#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace layermod {
namespace {

constexpr double kDepthNoiseShare = 0.02;
constexpr int kCellPx = 8;  // of OccluderBank::nearest_per_cell_mm_
constexpr std::uint16_t kNoDepthMm = 65535;

// PreparedRegion::depth_levels_mm in whole millimetres (CV_16U; rounded, negative and NaN
// become 0 = no depth), once per frame for all the comparisons.
std::vector<cv::Mat> WholeMillimetreDepths(const std::vector<cv::Mat>& depth_levels_mm) {
  std::vector<cv::Mat> whole_mm(depth_levels_mm.size());
  for (std::size_t level = 0; level < depth_levels_mm.size(); ++level) {
    depth_levels_mm[level].convertTo(whole_mm[level], CV_16U);
  }
  return whole_mm;
}

// The last whole millimetre nearer than `bound_mm` (0 is no depth).
double LastNearerMm(double bound_mm) { return std::ceil(bound_mm) - 1.0; }

// Per pyramid level of `whole_mm` (WholeMillimetreDepths), CV_8UC1, non-zero where the depth is
// valid and nearer than `bound_mm`; empty when no level-0 pixel is.
std::vector<cv::Mat> OccludersNearerThan(const std::vector<cv::Mat>& whole_mm, double bound_mm) {
  if (whole_mm.empty() || bound_mm <= 0.0) return {};
  std::vector<cv::Mat> masks(whole_mm.size());
  for (std::size_t level = 0; level < whole_mm.size(); ++level) {
    cv::inRange(whole_mm[level], 1.0, LastNearerMm(bound_mm), masks[level]);
    if (level == 0 && cv::countNonZero(masks[0]) == 0) return {};
  }
  return masks;
}

// The nearest valid depth of each kCellPx x kCellPx cell of `whole_mm` (CV_16U), kNoDepthMm in
// cells without one.
cv::Mat NearestPerCell(const cv::Mat& whole_mm) {
  cv::Mat nearest((whole_mm.rows + kCellPx - 1) / kCellPx, (whole_mm.cols + kCellPx - 1) / kCellPx,
                  CV_16U, cv::Scalar(kNoDepthMm));
  for (int y = 0; y < whole_mm.rows; ++y) {
    const auto* depth = whole_mm.ptr<std::uint16_t>(y);
    auto* cells = nearest.ptr<std::uint16_t>(y / kCellPx);
    for (int x = 0; x < whole_mm.cols; ++x) {
      if (depth[x] != 0) cells[x / kCellPx] = std::min(cells[x / kCellPx], depth[x]);
    }
  }
  return nearest;
}

// The last whole millimetre nearer than the layer's own bound.
double LastNearerMm(const LayerReach& layer) {
  return LastNearerMm(NearestSurfaceMm(layer.layer_depth_mm, layer.sphere_radius_mm));
}

}  // namespace

double NearestSurfaceMm(double layer_depth_mm, double sphere_radius_mm) {
  return layer_depth_mm * (1.0 - kDepthNoiseShare) - 1.5 * sphere_radius_mm;
}

int SharedBoundMm(double layer_depth_mm, double sphere_radius_mm) {
  const double bound_mm = NearestSurfaceMm(layer_depth_mm, sphere_radius_mm);
  return static_cast<int>(std::floor(bound_mm / kOccluderBoundStepMm)) * kOccluderBoundStepMm;
}

OccluderBank::OccluderBank(const PreparedRegion& prepared, std::span<const LayerReach> layers) {
  if (prepared.depth_levels_mm.empty()) return;
  const std::vector<cv::Mat> whole_mm = WholeMillimetreDepths(prepared.depth_levels_mm);
  whole_mm_ = whole_mm.front();
  nearest_per_cell_mm_ = NearestPerCell(whole_mm_);
  if (!prepared.outside_image.empty()) outside_image_ = prepared.outside_image.front();
  std::set<int> needed_mm;
  for (const LayerReach& layer : layers) {
    if (MayHaveNearerWithinReach(layer)) {
      needed_mm.insert(SharedBoundMm(layer.layer_depth_mm, layer.sphere_radius_mm));
    }
  }
  const std::vector<int> bounds(needed_mm.begin(), needed_mm.end());
  std::vector<std::optional<Occluders>> built(bounds.size());
  tbb::parallel_for(std::size_t{0}, bounds.size(), [&](std::size_t i) {
    std::vector<cv::Mat> masks = OccludersNearerThan(whole_mm, bounds[i]);
    if (masks.empty()) return;
    for (std::size_t level = 0; level < prepared.outside_image.size(); ++level) {
      masks[level] |= prepared.outside_image[level];
    }
    built[i] = MakeOccluders(prepared.scene, std::move(masks));
  });
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    by_bound_mm_.emplace(bounds[i], std::move(built[i]));
  }
}

const Occluders* OccluderBank::Find(int bound_mm) const {
  const auto found = by_bound_mm_.find(bound_mm);
  return found != by_bound_mm_.end() && found->second ? &*found->second : nullptr;
}

std::optional<Occluders> OccluderBank::ForLayer(const LayerReach& layer) const {
  const Occluders* shared = Find(SharedBoundMm(layer.layer_depth_mm, layer.sphere_radius_mm));
  if (shared == nullptr) return std::nullopt;
  cv::Mat mask = LevelZeroMask(layer);
  if (mask.empty()) return std::nullopt;
  return WithLevelZeroMask(*shared, std::move(mask));
}

bool OccluderBank::MayHaveNearerWithinReach(const LayerReach& layer) const {
  const cv::Rect reach = layer.reach_px & cv::Rect(cv::Point(0, 0), whole_mm_.size());
  if (reach.empty()) return false;
  const cv::Rect cells(
      cv::Point(reach.x / kCellPx, reach.y / kCellPx),
      cv::Point((reach.br().x + kCellPx - 1) / kCellPx, (reach.br().y + kCellPx - 1) / kCellPx));
  double nearest_mm = 0.0;
  cv::minMaxLoc(nearest_per_cell_mm_(cells), &nearest_mm);
  return nearest_mm <= LastNearerMm(layer);
}

cv::Mat OccluderBank::LevelZeroMask(const LayerReach& layer) const {
  const cv::Rect reach = layer.reach_px & cv::Rect(cv::Point(0, 0), whole_mm_.size());
  if (reach.empty()) return {};
  cv::Mat mask = cv::Mat::zeros(whole_mm_.size(), CV_8UC1);
  cv::Mat reached = mask(reach);
  cv::inRange(whole_mm_(reach), 1.0, LastNearerMm(layer), reached);
  if (cv::countNonZero(reached) == 0) return {};
  if (!outside_image_.empty()) reached |= outside_image_(reach);
  return mask;
}

}  // namespace layermod
