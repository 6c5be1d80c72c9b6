// SPDX-License-Identifier: MIT
#include "match/candidate_area.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace layermod {
namespace {

// Whether some disk pixel (within radius_px of a point, and no farther from the image than
// MakeCandidateArea keeps: [-W, 2W) x [-H, 2H)) lies in the window [x0, x0 + span) x
// [y0, y0 + span): the nearest pixel of the window's kept part to each point, by definition.
bool WindowReachesAPoint(const std::vector<cv::Point>& points, int radius_px, cv::Size image,
                         int x0, int y0, int span) {
  const int left = std::max(x0, -image.width);
  const int right = std::min(x0 + span - 1, 2 * image.width - 1);
  const int top = std::max(y0, -image.height);
  const int bottom = std::min(y0 + span - 1, 2 * image.height - 1);
  if (left > right || top > bottom) return false;
  for (const cv::Point& point : points) {
    const int dx = std::clamp(point.x, left, right) - point.x;
    const int dy = std::clamp(point.y, top, bottom) - point.y;
    if (dx * dx + dy * dy <= radius_px * radius_px) return true;
  }
  return false;
}

// The near cells of NearCells as a grid of flags.
cv::Mat NearCellFlags(const CandidateArea& area, int span, cv::Point anchor, cv::Size cells) {
  std::vector<GridRowSpan> spans;
  NearCells(span, anchor, cells, area, spans);
  cv::Mat flags = cv::Mat::zeros(cells, CV_8U);
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const GridRowSpan& run = spans[i];
    if (i > 0) {  // scan order, maximal runs
      const GridRowSpan& before = spans[i - 1];
      EXPECT_TRUE(before.row < run.row ||
                  (before.row == run.row && before.last_column + 1 < run.first_column));
    }
    for (int gx = run.first_column; gx <= run.last_column; ++gx)
      flags.at<std::uint8_t>(run.row, gx) = 1;
  }
  return flags;
}

TEST(CandidateAreaTest, NearCellsAreTheCellsWhoseAnchorWindowReachesADisk) {
  cv::RNG rng(97);
  const cv::Size image(160, 120);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<cv::Point> points;
    const int count = rng.uniform(1, 12);
    for (int i = 0; i < count; ++i) {  // some outside the image, one far outside
      points.emplace_back(rng.uniform(-60, image.width + 60), rng.uniform(-60, image.height + 60));
    }
    if (trial == 5) points.emplace_back(-400, 50);
    const int radius_px = rng.uniform(0, 30);
    const std::array<int, 3> spans = {4, 8, 8};
    const CandidateArea area = MakeCandidateArea(points, radius_px, image, spans);
    ASSERT_TRUE(area.restricted);
    ASSERT_EQ(area.by_span.size(), 2u);  // one reach per distinct span
    for (const int span : {4, 8}) {
      const cv::Size cells(image.width / span + 4, image.height / span + 4);
      for (int k = 0; k < 5; ++k) {
        const cv::Point anchor(rng.uniform(-20, 50), rng.uniform(-20, 50));
        const cv::Mat flags = NearCellFlags(area, span, anchor, cells);
        for (int gy = 0; gy < cells.height; ++gy) {
          for (int gx = 0; gx < cells.width; ++gx) {
            const bool near = WindowReachesAPoint(points, radius_px, image, gx * span + anchor.x,
                                                  gy * span + anchor.y, span);
            ASSERT_EQ(flags.at<std::uint8_t>(gy, gx) != 0, near)
                << "trial " << trial << " span " << span << " cell (" << gx << ", " << gy
                << ") anchor " << anchor;
          }
        }
      }
    }
  }
}

TEST(CandidateAreaTest, NoPointsReachNothingAndAnUnknownSpanNothing) {
  const std::array<int, 1> spans = {8};
  const CandidateArea none = MakeCandidateArea({}, 10, cv::Size(64, 48), spans);
  EXPECT_TRUE(none.restricted);
  std::vector<GridRowSpan> cells = {{0, 0, 0}};
  NearCells(8, cv::Point(0, 0), cv::Size(8, 6), none, cells);
  EXPECT_TRUE(cells.empty());
  const CandidateArea some = MakeCandidateArea({cv::Point(20, 20)}, 10, cv::Size(64, 48), spans);
  NearCells(8, cv::Point(0, 0), cv::Size(8, 6), some, cells);
  EXPECT_FALSE(cells.empty());
  NearCells(16, cv::Point(0, 0), cv::Size(4, 3), some, cells);
  EXPECT_TRUE(cells.empty());
}

}  // namespace
}  // namespace layermod
