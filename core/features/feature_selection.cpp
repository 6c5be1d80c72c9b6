// SPDX-License-Identifier: MIT
#include "features/feature_selection.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "util/error.h"

namespace layermod {
namespace {

// Maps a score to an unsigned key that orders like the score, descending.
std::uint32_t DescendingScoreKey(float score) {
  std::uint32_t bits;
  std::memcpy(&bits, &score, sizeof bits);
  const std::uint32_t ascending = (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
  return ~ascending;
}

bool RasterBefore(const FeatureCandidate& a, const FeatureCandidate& b) {
  if (a.y != b.y) return a.y < b.y;
  if (a.x != b.x) return a.x < b.x;
  return a.label < b.label;
}

// Orders by score (descending), ties by y, x, label. Candidates usually come in raster order
// already (they are collected row by row), so a stable radix sort on the score alone does it in
// linear time; sorting dominated extraction with a comparison sort.
void SortByScore(std::vector<FeatureCandidate>* candidates) {
  if (!std::is_sorted(candidates->begin(), candidates->end(), RasterBefore)) {
    std::sort(candidates->begin(), candidates->end(), RasterBefore);
  }
  const size_t n = candidates->size();
  std::vector<std::uint32_t> keys(n), order(n), next_keys(n), next_order(n);
  for (size_t i = 0; i < n; ++i) {
    keys[i] = DescendingScoreKey((*candidates)[i].score);
    order[i] = static_cast<std::uint32_t>(i);
  }
  // Histograms of the four key bytes in one pass; a byte that all keys share needs no pass.
  constexpr size_t kBuckets = 257;  // per byte, with a leading 0 for prefix sums
  std::vector<std::uint32_t> start(4 * kBuckets, 0u);
  for (size_t i = 0; i < n; ++i) {
    for (size_t b = 0; b < 4; ++b) ++start[b * kBuckets + ((keys[i] >> (8 * b)) & 0xFFu) + 1];
  }
  for (size_t b = 0; b < 4; ++b) {  // least significant byte first: each pass is stable
    std::uint32_t* begin = start.data() + b * kBuckets;
    std::uint32_t* end = begin + kBuckets;
    if (std::find(begin + 1, end, static_cast<std::uint32_t>(n)) != end) continue;
    for (int v = 0; v < 256; ++v) begin[v + 1] += begin[v];
    for (size_t i = 0; i < n; ++i) {
      const std::uint32_t to = begin[(keys[i] >> (8 * b)) & 0xFFu]++;
      next_keys[to] = keys[i];
      next_order[to] = order[i];
    }
    keys.swap(next_keys);
    order.swap(next_order);
  }
  std::vector<FeatureCandidate> sorted(n);
  for (size_t i = 0; i < n; ++i) sorted[i] = (*candidates)[order[i]];
  *candidates = std::move(sorted);
}

Feature ToFeature(const FeatureCandidate& candidate, Modality modality) {
  return {static_cast<std::int16_t>(candidate.x), static_cast<std::int16_t>(candidate.y),
          candidate.label, modality};
}

// Squared distance from every pixel of the candidates' box to the nearest kept feature, filled only
// within the distance in force when the feature was kept: the distance only shrinks, so farther
// pixels can never be too close to it. Checking a candidate is then one load, and filling costs
// about 4 x the box area in total however many features are kept.
class NearestKeptMap {
 public:
  explicit NearestKeptMap(cv::Rect bounds)
      : bounds_(bounds),
        distance_sq_(bounds.size(), CV_32F, cv::Scalar(std::numeric_limits<float>::infinity())) {}

  void Add(int x, int y, float distance) {
    const int radius = static_cast<int>(std::ceil(distance));
    const int cx = x - bounds_.x, cy = y - bounds_.y;
    const int x_begin = std::max(cx - radius, 0), x_end = std::min(cx + radius, bounds_.width - 1);
    const int y_begin = std::max(cy - radius, 0), y_end = std::min(cy + radius, bounds_.height - 1);
    if (x_begin > x_end) return;
    dx_sq_.resize(x_end - x_begin + 1);
    for (int px = x_begin; px <= x_end; ++px) {
      dx_sq_[px - x_begin] = static_cast<float>((px - cx) * (px - cx));
    }
    const float* __restrict dx_sq = dx_sq_.data();
    for (int py = y_begin; py <= y_end; ++py) {
      float* __restrict row = distance_sq_.ptr<float>(py) + x_begin;
      const auto dy_sq = static_cast<float>((py - cy) * (py - cy));
      for (int i = 0; i <= x_end - x_begin; ++i) row[i] = std::min(row[i], dy_sq + dx_sq[i]);
    }
  }

  float DistanceSq(int x, int y) const {
    return distance_sq_.at<float>(y - bounds_.y, x - bounds_.x);
  }

 private:
  cv::Rect bounds_;
  cv::Mat distance_sq_;
  std::vector<float> dx_sq_;  // (x - centre)^2 of the columns being filled
};

cv::Rect CandidateBounds(const std::vector<FeatureCandidate>& candidates) {
  int min_x = std::numeric_limits<int>::max(), min_y = min_x;
  int max_x = std::numeric_limits<int>::min(), max_y = max_x;
  for (const FeatureCandidate& c : candidates) {
    min_x = std::min(min_x, c.x), max_x = std::max(max_x, c.x);
    min_y = std::min(min_y, c.y), max_y = std::max(max_y, c.y);
  }
  return {min_x, min_y, max_x - min_x + 1, max_y - min_y + 1};
}

void CheckPositions(const std::vector<FeatureCandidate>& candidates) {
  constexpr int kMin = std::numeric_limits<std::int16_t>::min();
  constexpr int kMax = std::numeric_limits<std::int16_t>::max();
  for (const FeatureCandidate& c : candidates) {
    if (c.x < kMin || c.x > kMax || c.y < kMin || c.y > kMax || c.label > 7) {
      throw Error("SelectScatteredFeatures: candidate position beyond int16 or label beyond 7");
    }
  }
}

}  // namespace

std::vector<Feature> SelectScatteredFeatures(std::vector<FeatureCandidate> candidates, int count,
                                             Modality modality) {
  std::vector<Feature> kept;
  if (count <= 0 || candidates.empty()) return kept;
  CheckPositions(candidates);
  SortByScore(&candidates);
  if (static_cast<int>(candidates.size()) <= count) {
    for (const FeatureCandidate& c : candidates) kept.push_back(ToFeature(c, modality));
    return kept;
  }
  const cv::Rect bounds = CandidateBounds(candidates);
  float distance_sq = static_cast<float>(bounds.area()) / static_cast<float>(count);
  NearestKeptMap nearest(bounds);
  // Candidates not kept yet, in score order, with their squared distance to the nearest kept
  // feature when last looked up: that distance only shrinks, so a candidate already closer than
  // the current distance is passed over without looking it up again.
  struct Waiting {
    std::uint32_t index;
    float nearest_sq;
  };
  std::vector<Waiting> waiting(candidates.size());
  for (size_t i = 0; i < waiting.size(); ++i) {
    waiting[i] = {static_cast<std::uint32_t>(i), std::numeric_limits<float>::infinity()};
  }
  kept.reserve(count);
  while (static_cast<int>(kept.size()) < count) {
    const float distance = std::sqrt(distance_sq);
    float farthest_rejected_sq = 0.0f;
    size_t still_waiting = 0;
    for (size_t i = 0; i < waiting.size(); ++i) {
      Waiting w = waiting[i];
      if (!(w.nearest_sq < distance_sq) && static_cast<int>(kept.size()) < count) {
        const FeatureCandidate& c = candidates[w.index];
        w.nearest_sq = nearest.DistanceSq(c.x, c.y);
        if (!(w.nearest_sq < distance_sq)) {
          kept.push_back(ToFeature(c, modality));
          nearest.Add(c.x, c.y, distance);
          continue;
        }
      }
      farthest_rejected_sq = std::max(farthest_rejected_sq, w.nearest_sq);
      waiting[still_waiting++] = w;
    }
    waiting.resize(still_waiting);
    // Shrink by 10 % (at least 1 px), or further straight to where the next waiting candidate
    // becomes far enough: passes that would keep nothing are skipped. Distance 0 keeps all.
    const float shrunk = std::max(0.0f, std::min(distance - 1.0f, distance * 0.9f));
    distance_sq = std::min(shrunk * shrunk, farthest_rejected_sq);
  }
  return kept;
}

}  // namespace layermod
