// SPDX-License-Identifier: MIT
#include "pipeline/layer_occluders.h"

#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>

#include <cmath>

namespace layermod {

constexpr double kDepthNoiseShare = 0.02;

double NearestSurfaceMm(double layer_depth_mm, double sphere_radius_mm) {
  return layer_depth_mm * (1.0 - kDepthNoiseShare) - 1.5 * sphere_radius_mm;
}

std::vector<cv::Mat> WholeMillimetreDepths(const std::vector<cv::Mat>& depth_levels_mm) {
  std::vector<cv::Mat> whole_mm(depth_levels_mm.size());
  for (std::size_t level = 0; level < depth_levels_mm.size(); ++level) {
    depth_levels_mm[level].convertTo(whole_mm[level], CV_16U);
  }
  return whole_mm;
}

namespace {

// `reach_px` (level-0 pixels) on the pyramid level `level` of size `size`.
cv::Rect ReachOnLevel(const cv::Rect& reach_px, std::size_t level, const cv::Size& size) {
  const int scale = 1 << level;
  return cv::Rect(cv::Point(reach_px.x / scale, reach_px.y / scale),
                  cv::Point((reach_px.br().x + scale - 1) / scale,
                            (reach_px.br().y + scale - 1) / scale)) &
         cv::Rect(cv::Point(0, 0), size);
}

}  // namespace

std::vector<cv::Mat> OccludersNearerThan(const std::vector<cv::Mat>& depth_levels_mm,
                                         double nearest_surface_mm, const cv::Rect& reach_px) {
  if (depth_levels_mm.empty() || nearest_surface_mm <= 0.0) return {};
  // Whole millimetres from 1 (0 is no depth) to the last one nearer than the bound.
  const double last_mm = std::ceil(nearest_surface_mm) - 1.0;
  std::vector<cv::Mat> masks;
  masks.reserve(depth_levels_mm.size());
  for (std::size_t level = 0; level < depth_levels_mm.size(); ++level) {
    const cv::Mat& depth = depth_levels_mm[level];
    const cv::Rect reach = ReachOnLevel(reach_px, level, depth.size());
    cv::Mat reached;
    if (!reach.empty()) cv::inRange(depth(reach), 1.0, last_mm, reached);
    // Most layers of a frame have nothing in front: known from level 0 alone.
    if (level == 0 && (reached.empty() || cv::countNonZero(reached) == 0)) return {};
    cv::Mat mask = cv::Mat::zeros(depth.size(), CV_8UC1);
    if (!reached.empty()) reached.copyTo(mask(reach));
    masks.push_back(mask);
  }
  return masks;
}

int SharedBoundMm(double layer_depth_mm, double sphere_radius_mm) {
  const double bound_mm = NearestSurfaceMm(layer_depth_mm, sphere_radius_mm);
  return static_cast<int>(std::floor(bound_mm / kOccluderBoundStepMm)) * kOccluderBoundStepMm;
}

OccluderBank::OccluderBank(const PreparedRegion& prepared, std::span<const LayerReach> layers) {
  if (prepared.depth_levels_mm.empty()) return;
  const std::vector<cv::Mat> whole_mm = WholeMillimetreDepths(prepared.depth_levels_mm);
  whole_mm_ = whole_mm.front();
  if (!prepared.outside_image.empty()) outside_image_ = prepared.outside_image.front();
  std::vector<char> in_front(layers.size(), 0);
  tbb::parallel_for(std::size_t{0}, layers.size(),
                    [&](std::size_t i) { in_front[i] = AnyNearerWithinReach(layers[i]); });
  std::set<int> needed_mm;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    if (in_front[i]) {
      needed_mm.insert(SharedBoundMm(layers[i].layer_depth_mm, layers[i].sphere_radius_mm));
    }
  }
  const cv::Rect region(cv::Point(0, 0), whole_mm_.size());
  const std::vector<int> bounds(needed_mm.begin(), needed_mm.end());
  std::vector<std::optional<Occluders>> built(bounds.size());
  tbb::parallel_for(std::size_t{0}, bounds.size(), [&](std::size_t i) {
    std::vector<cv::Mat> masks = OccludersNearerThan(whole_mm, bounds[i], region);
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

namespace {

// The last whole millimetre nearer than the layer's own bound (0 is no depth).
double LastNearerMm(const LayerReach& layer) {
  return std::ceil(NearestSurfaceMm(layer.layer_depth_mm, layer.sphere_radius_mm)) - 1.0;
}

}  // namespace

bool OccluderBank::AnyNearerWithinReach(const LayerReach& layer) const {
  const cv::Rect reach = layer.reach_px & cv::Rect(cv::Point(0, 0), whole_mm_.size());
  if (reach.empty()) return false;
  cv::Mat nearer;
  cv::inRange(whole_mm_(reach), 1.0, LastNearerMm(layer), nearer);
  return cv::countNonZero(nearer) > 0;
}

cv::Mat OccluderBank::NearerWithinReach(const LayerReach& layer) const {
  const cv::Rect reach = layer.reach_px & cv::Rect(cv::Point(0, 0), whole_mm_.size());
  if (reach.empty()) return {};
  cv::Mat mask = cv::Mat::zeros(whole_mm_.size(), CV_8UC1);
  cv::Mat reached = mask(reach);
  cv::inRange(whole_mm_(reach), 1.0, LastNearerMm(layer), reached);
  return cv::countNonZero(reached) > 0 ? mask : cv::Mat();
}

std::optional<Occluders> OccluderBank::ForLayer(const LayerReach& layer) const {
  const Occluders* shared = Find(SharedBoundMm(layer.layer_depth_mm, layer.sphere_radius_mm));
  if (shared == nullptr) return std::nullopt;
  cv::Mat mask = NearerWithinReach(layer);
  if (mask.empty()) return std::nullopt;
  if (!outside_image_.empty()) {
    const cv::Rect reach = layer.reach_px & cv::Rect(cv::Point(0, 0), whole_mm_.size());
    cv::Mat reached = mask(reach);
    reached |= outside_image_(reach);
  }
  return WithLevelZeroMask(*shared, std::move(mask));
}

}  // namespace layermod
