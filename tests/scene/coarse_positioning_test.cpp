// SPDX-License-Identifier: MIT
#include "scene/coarse_positioning.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "util/error.h"

namespace layermod {
namespace {

const std::vector<double> kLayers = {650.0, 750.0, 850.0, 950.0};
constexpr double kRadius = 50.0;
constexpr double kFocal = 500.0;

// Square "objects" (raised boxes) at 740 mm on a table at 900 mm; object side ~ 0.7 * f*R/z.
cv::Mat Scene(const std::vector<cv::Rect>& boxes) {
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(900.0f));
  for (const cv::Rect& box : boxes) depth(box).setTo(740.0f);
  return depth;
}

// Edge pixels of an axis-aligned box silhouette: two-pixel-wide outline of its perimeter.
cv::Mat EdgesOf(const cv::Mat& depth) {
  cv::Mat grad_x, grad_y, magnitude;
  cv::Sobel(depth, grad_x, CV_32F, 1, 0);
  cv::Sobel(depth, grad_y, CV_32F, 0, 1);
  cv::magnitude(grad_x, grad_y, magnitude);
  return magnitude / 4.0f > 30.0f;
}

std::vector<LayerEdgeRange> RangesForBoxSide(int side_px) {
  // A square of side a has a ~2-pixel-wide silhouette edge of about 8a pixels.
  std::vector<LayerEdgeRange> ranges(kLayers.size());
  ranges[1] = {6 * side_px, 9 * side_px, true};
  return ranges;
}

TEST(CoarsePositioningTest, KeepsPointsOnTheObjectAndRejectsFlatTable) {
  const cv::Rect box(300, 200, 40, 40);
  const cv::Mat depth = Scene({box});
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  CoarsePositioningOptions options;
  options.max_blocks = 0;
  const CoarsePositioning result = PositionCoarsely(division, depth, EdgesOf(depth), kFocal,
                                                    2 * kRadius, RangesForBoxSide(40), options);
  ASSERT_FALSE(result.kept.empty());
  const auto kept = result.KeptPoints();
  ASSERT_FALSE(kept.empty());
  for (const DetectionPoint& point : kept) {
    EXPECT_TRUE(
        cv::Rect(box.x - 8, box.y - 8, box.width + 16, box.height + 16).contains(point.pixel))
        << point.pixel;
  }
  // The table layer (950 mm) has no template range: its block is not evaluated at all.
  for (const BlockCandidates& block : result.evaluated) {
    EXPECT_EQ(division.blocks[static_cast<std::size_t>(block.block_index)].layer_index, 1);
  }
}

TEST(CoarsePositioningTest, EdgeCountsAreScaledToTheLayerDepth) {
  // The same box at 650 mm (nearer than its 750 mm layer): counts scale by z / D.
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(900.0f));
  depth(cv::Rect(300, 200, 40, 40)).setTo(720.0f);
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  const CoarsePositioning result =
      PositionCoarsely(division, depth, EdgesOf(depth), kFocal, 2 * kRadius, RangesForBoxSide(40));
  ASSERT_FALSE(result.evaluated.empty());
  const cv::Mat edges = EdgesOf(depth);
  for (const DetectionPoint& point : result.evaluated[0].points) {
    const int size = static_cast<int>(std::lround(kFocal * 2 * kRadius / point.depth_mm));
    const cv::Rect window =
        cv::Rect(point.pixel.x - size / 2, point.pixel.y - size / 2, size, size) &
        cv::Rect(0, 0, 640, 480);
    const double raw = cv::countNonZero(edges(window));
    EXPECT_NEAR(point.edge_count, raw * point.depth_mm / 750.0, 1e-3);
  }
}

TEST(CoarsePositioningTest, KeepsOnlyTheBestBlocks) {
  // Two objects in different layers; the one matching the template counts wins.
  cv::Mat depth(480, 640, CV_32F, cv::Scalar(900.0f));
  depth(cv::Rect(100, 100, 40, 40)).setTo(750.0f);
  depth(cv::Rect(400, 300, 12, 12)).setTo(650.0f);
  std::vector<LayerEdgeRange> ranges(kLayers.size(), LayerEdgeRange{240, 360, true});
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  CoarsePositioningOptions options;
  options.max_blocks = 1;
  const CoarsePositioning result =
      PositionCoarsely(division, depth, EdgesOf(depth), kFocal, 2 * kRadius, ranges, options);
  ASSERT_EQ(result.kept.size(), 1u);
  const auto& best = result.evaluated[static_cast<std::size_t>(result.kept[0])];
  EXPECT_EQ(division.blocks[static_cast<std::size_t>(best.block_index)].layer_index, 1);
}

TEST(CoarsePositioningTest, UpperFactorBoundsTheEdgeCountOfClutteredPoints) {
  // Two 30-px boxes 6 px apart: a window on one also sees much of the other's outline
  // (270-390 edge pixels, where one box alone has about 240), so with templates whose counts
  // reach N_max = 230 some points pass 2.0 N_max but not 1.5 N_max.
  const cv::Mat depth = Scene({cv::Rect(290, 200, 30, 30), cv::Rect(326, 200, 30, 30)});
  const cv::Mat edges = EdgesOf(depth);
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  std::vector<LayerEdgeRange> ranges(kLayers.size());
  ranges[1] = {200, 230, true};
  std::vector<int> kept_counts;
  for (float upper : {1.5f, 2.0f}) {
    CoarsePositioningOptions options;
    options.max_blocks = 0;
    options.upper_factor = upper;
    const CoarsePositioning result =
        PositionCoarsely(division, depth, edges, kFocal, 2 * kRadius, ranges, options);
    int kept = 0;
    for (const BlockCandidates& block : result.evaluated) {
      for (const DetectionPoint& point : block.points) {
        const bool within = point.edge_count >= options.lower_factor * ranges[1].n_min &&
                            point.edge_count <= upper * ranges[1].n_max;
        EXPECT_EQ(point.kept, within) << point.pixel << " count " << point.edge_count;
        kept += point.kept ? 1 : 0;
      }
    }
    kept_counts.push_back(kept);
  }
  EXPECT_GT(kept_counts[1], kept_counts[0]);
}

TEST(CoarsePositioningTest, NoEdgesMeansNothingKept) {
  const cv::Mat depth(240, 320, CV_32F, cv::Scalar(750.0f));
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  std::vector<LayerEdgeRange> ranges(kLayers.size(), LayerEdgeRange{100, 200, true});
  const CoarsePositioning result = PositionCoarsely(
      division, depth, cv::Mat::zeros(depth.size(), CV_8U), kFocal, 2 * kRadius, ranges);
  EXPECT_TRUE(result.kept.empty());
  EXPECT_TRUE(result.KeptPoints().empty());
  EXPECT_FALSE(result.evaluated.empty());
}

TEST(CoarsePositioningTest, RejectsMismatchedInputs) {
  const cv::Mat depth(240, 320, CV_32F, cv::Scalar(750.0f));
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  std::vector<LayerEdgeRange> ranges(kLayers.size(), LayerEdgeRange{100, 200, true});
  EXPECT_THROW(
      PositionCoarsely(division, depth, cv::Mat::zeros(10, 10, CV_8U), kFocal, 100, ranges), Error);
  EXPECT_THROW(
      PositionCoarsely(division, depth, cv::Mat::zeros(depth.size(), CV_8U), 0.0, 100, ranges),
      Error);
  CoarsePositioningOptions options;
  options.point_step_px = 0;
  EXPECT_THROW(PositionCoarsely(division, depth, cv::Mat::zeros(depth.size(), CV_8U), kFocal, 100,
                                ranges, options),
               Error);
}

}  // namespace
}  // namespace layermod
