// SPDX-License-Identifier: MIT
#include "match/candidate_area.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace layermod {

namespace {

int FloorDiv(int value, int divisor) {
  return value >= 0 ? value / divisor : -((-value + divisor - 1) / divisor);
}

// The level-0 pixels within radius_px of some point, inside `bounds`: CV_8U over `bounds`, 1 on
// the disks.
cv::Mat StampDisks(const std::vector<cv::Point>& points, int radius_px, const cv::Rect& bounds) {
  cv::Mat disks = cv::Mat::zeros(bounds.size(), CV_8U);
  const double radius_sq = static_cast<double>(radius_px) * radius_px;
  for (const cv::Point& point : points) {
    const int y0 = std::max(point.y - radius_px, bounds.y);
    const int y1 = std::min(point.y + radius_px, bounds.br().y - 1);
    for (int y = y0; y <= y1; ++y) {
      const double dy = y - point.y;
      const int half = static_cast<int>(std::floor(std::sqrt(radius_sq - dy * dy)));
      const int x0 = std::max(point.x - half, bounds.x);
      const int x1 = std::min(point.x + half, bounds.br().x - 1);
      if (x0 > x1) continue;
      std::uint8_t* row = disks.ptr<std::uint8_t>(y - bounds.y);
      std::fill(row + (x0 - bounds.x), row + (x1 - bounds.x) + 1, std::uint8_t{1});
    }
  }
  return disks;
}

// The runs of ones of each row of a 0/1 map, as [first, last] columns, row after row: the
// phases read them instead of the map's pixels (a run yields a phase's cells in one step).
struct RowRuns {
  std::vector<std::size_t> row_begin;  // rows + 1 offsets into `runs`
  std::vector<cv::Vec2i> runs;
};

RowRuns RunsOfRows(const cv::Mat& map) {
  RowRuns result;
  result.row_begin.reserve(static_cast<std::size_t>(map.rows) + 1);
  for (int y = 0; y < map.rows; ++y) {
    result.row_begin.push_back(result.runs.size());
    const std::uint8_t* row = map.ptr<std::uint8_t>(y);
    const auto width = static_cast<std::size_t>(map.cols);
    std::size_t at = 0;
    while (at < width) {
      const void* one = std::memchr(row + at, 1, width - at);
      if (one == nullptr) break;
      const auto first = static_cast<std::size_t>(static_cast<const std::uint8_t*>(one) - row);
      const void* zero = std::memchr(row + first, 0, width - first);
      const std::size_t past =
          zero == nullptr ? width
                          : static_cast<std::size_t>(static_cast<const std::uint8_t*>(zero) - row);
      result.runs.emplace_back(static_cast<int>(first), static_cast<int>(past) - 1);
      at = past;
    }
  }
  result.row_begin.push_back(result.runs.size());
  return result;
}

// The non-zero cells of phase (rx, ry) of a reach map of `size` (see CandidateArea::Reach),
// from the runs of its rows: cell jx of a sampled row is non-zero iff its pixel jx * span - rx
// lies in one of the row's runs.
std::vector<GridRowSpan> PhaseRuns(const RowRuns& reach, cv::Size size, int span, int rx, int ry) {
  std::vector<GridRowSpan> runs;
  const int cols = (size.width - 1 + rx) / span + 1;
  const int rows = (size.height - 1 + ry) / span + 1;
  const int first_column = rx > 0 ? 1 : 0;
  for (int jy = ry > 0 ? 1 : 0; jy < rows; ++jy) {
    const auto y = static_cast<std::size_t>(jy * span - ry);
    for (std::size_t k = reach.row_begin[y]; k < reach.row_begin[y + 1]; ++k) {
      const cv::Vec2i& run = reach.runs[k];
      const int jx0 = std::max((run[0] + rx + span - 1) / span, first_column);
      const int jx1 = std::min((run[1] + rx) / span, cols - 1);
      if (jx0 > jx1) continue;
      if (!runs.empty() && runs.back().row == jy && runs.back().last_column == jx0 - 1) {
        runs.back().last_column = jx1;
      } else {
        runs.push_back({jy, jx0, jx1});
      }
    }
  }
  return runs;
}

// The reach of `disks` (over `disks_box`) for cells of `span` pixels.
CandidateArea::Reach MakeReach(const cv::Mat& disks, const cv::Rect& disks_box, int span) {
  // A window starting up to span - 1 pixels left of or above the disks still reaches them.
  CandidateArea::Reach reach{span, disks_box.tl() - cv::Point(span - 1, span - 1), {}};
  cv::Mat padded = cv::Mat::zeros(disks_box.height + span - 1, disks_box.width + span - 1, CV_8U);
  disks.copyTo(padded(cv::Rect(cv::Point(span - 1, span - 1), disks_box.size())));
  cv::Mat reach_map;
  cv::dilate(padded, reach_map, cv::Mat::ones(span, span, CV_8U), cv::Point(0, 0), 1,
             cv::BORDER_CONSTANT, cv::Scalar(0));
  const RowRuns row_runs = RunsOfRows(reach_map);
  reach.phase_runs.reserve(static_cast<std::size_t>(span) * static_cast<std::size_t>(span));
  for (int ry = 0; ry < span; ++ry) {
    for (int rx = 0; rx < span; ++rx) {
      reach.phase_runs.push_back(PhaseRuns(row_runs, reach_map.size(), span, rx, ry));
    }
  }
  return reach;
}

}  // namespace

const CandidateArea::Reach* CandidateArea::ForSpan(int span) const {
  for (const Reach& reach : by_span) {
    if (reach.span == span) return &reach;
  }
  return nullptr;
}

CandidateArea MakeCandidateArea(const std::vector<cv::Point>& points, int radius_px, cv::Size image,
                                std::span<const int> spans) {
  CandidateArea area;
  area.restricted = true;
  if (points.empty()) return area;
  cv::Rect disks_box;
  for (const cv::Point& point : points) {
    disks_box |= cv::Rect(point - cv::Point(radius_px, radius_px),
                          cv::Size(2 * radius_px + 1, 2 * radius_px + 1));
  }
  disks_box &= cv::Rect(-image.width, -image.height, 3 * image.width, 3 * image.height);
  if (disks_box.empty()) return area;
  const cv::Mat disks = StampDisks(points, radius_px, disks_box);
  for (const int span : spans) {
    if (area.ForSpan(span) == nullptr) area.by_span.push_back(MakeReach(disks, disks_box, span));
  }
  return area;
}

void NearCells(int span, cv::Point anchor, const cv::Size& cells, const CandidateArea& area,
               std::vector<GridRowSpan>& spans) {
  spans.clear();
  const CandidateArea::Reach* reach = area.ForSpan(span);
  if (reach == nullptr) return;
  const cv::Point first = reach->origin - anchor;  // window corner of reach(0, 0)
  const cv::Point shift(FloorDiv(first.x, span), FloorDiv(first.y, span));
  const cv::Point residue = first - shift * span;
  const std::vector<GridRowSpan>& runs =
      reach->phase_runs[static_cast<std::size_t>(residue.y) * span + residue.x];
  for (const GridRowSpan& run : runs) {
    const int gy = run.row + shift.y;
    if (gy < 0 || gy >= cells.height) continue;
    const int gx0 = std::max(run.first_column + shift.x, 0);
    const int gx1 = std::min(run.last_column + shift.x, cells.width - 1);
    if (gx0 <= gx1) spans.push_back({gy, gx0, gx1});
  }
}

}  // namespace layermod
