// SPDX-License-Identifier: MIT
#include "scene/region_division.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "scene/depth_mm.h"
#include "util/error.h"

namespace layermod {
namespace {

const std::vector<double> kLayers = {650.0, 750.0, 850.0, 950.0, 1050.0};
constexpr double kRadius = 100.0;

// A table plane at 1000 mm with a box-shaped object at 740 mm in front of it.
cv::Mat TableWithBox(cv::Size size, cv::Rect box) {
  cv::Mat depth(size, CV_32F, cv::Scalar(1000.0f));
  depth(box).setTo(740.0f);
  return depth;
}

const SceneBlock* BlockAt(const RegionDivision& division, cv::Point pixel) {
  for (const SceneBlock& block : division.blocks) {
    if (division.BlockContains(block, pixel)) return &block;
  }
  return nullptr;
}

TEST(RegionDivisionTest, SeparatesObjectFromBackgroundByLayer) {
  const cv::Mat depth = TableWithBox({640, 480}, {200, 150, 120, 100});
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  const SceneBlock* object = BlockAt(division, {260, 200});
  const SceneBlock* table = BlockAt(division, {20, 20});
  ASSERT_NE(object, nullptr);
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(object->layer_depth_mm, 750.0);
  EXPECT_EQ(table->layer_depth_mm, 950.0);
  EXPECT_TRUE(object->bbox_px.contains({205, 155}));
  // The object's block hugs the box (cells may round it up by one cell on each side).
  EXPECT_LE(object->bbox_px.width, 120 + 2 * 8);
  EXPECT_LE(object->bbox_px.height, 100 + 2 * 8);
}

TEST(RegionDivisionTest, SlopedSurfaceSplitsIntoSeveralLayers) {
  // Depth grows linearly from 650 to 1050 mm across the image.
  cv::Mat depth(240, 400, CV_32F);
  for (int y = 0; y < depth.rows; ++y) {
    for (int x = 0; x < depth.cols; ++x) depth.at<float>(y, x) = 650.0f + x;
  }
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  std::set<int> layers;
  for (const SceneBlock& block : division.blocks) layers.insert(block.layer_index);
  EXPECT_GE(layers.size(), 3u);
  // A point is attached to a layer whose depth is within one radius of its own.
  for (int x : {10, 150, 300, 390}) {
    const SceneBlock* block = BlockAt(division, {x, 120});
    ASSERT_NE(block, nullptr) << x;
    EXPECT_LE(std::abs(block->layer_depth_mm - (650.0 + x)), kRadius + 8) << x;
  }
}

TEST(RegionDivisionTest, InvalidDepthIsNeverPartOfABlock) {
  cv::Mat depth = TableWithBox({320, 240}, {100, 80, 60, 60});
  depth(cv::Rect(0, 0, 320, 40)).setTo(0.0f);
  depth(cv::Rect(0, 200, 320, 40)).setTo(std::numeric_limits<float>::quiet_NaN());
  const RegionDivision division = DivideScene(DepthToMillimetres(depth), kLayers, kRadius);
  EXPECT_EQ(BlockAt(division, {10, 10}), nullptr);
  EXPECT_EQ(BlockAt(division, {10, 230}), nullptr);
  EXPECT_NE(BlockAt(division, {10, 120}), nullptr);
}

TEST(RegionDivisionTest, AllZeroDepthGivesNoBlocks) {
  const cv::Mat depth = cv::Mat::zeros(480, 640, CV_32F);
  EXPECT_TRUE(DivideScene(depth, kLayers, kRadius).blocks.empty());
}

TEST(RegionDivisionTest, DepthFarFromEveryLayerIsDropped) {
  const cv::Mat depth(200, 200, CV_32F, cv::Scalar(3000.0f));
  EXPECT_TRUE(DivideScene(depth, kLayers, kRadius).blocks.empty());
}

TEST(RegionDivisionTest, AnyImageSizeWorks) {
  const cv::Mat depth = TableWithBox({101, 77}, {30, 20, 40, 30});
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  EXPECT_NE(BlockAt(division, {50, 35}), nullptr);
  EXPECT_NE(BlockAt(division, {100, 76}), nullptr);
  EXPECT_EQ(BlockAt(division, {101, 76}), nullptr);
}

TEST(RegionDivisionTest, RejectsBadArguments) {
  const cv::Mat depth(10, 10, CV_32F, cv::Scalar(700.0f));
  EXPECT_THROW(DivideScene(depth, {}, kRadius), Error);
  EXPECT_THROW(DivideScene(depth, kLayers, 0.0), Error);
  RegionDivisionOptions options;
  options.cell_size_px = 0;
  EXPECT_THROW(DivideScene(depth, kLayers, kRadius, options), Error);
}

TEST(RegionDivisionTest, DividingPrecomputedCellDepthsGivesTheSameBlocks) {
  cv::Mat depth = TableWithBox({203, 157}, {40, 30, 60, 50});
  depth(cv::Rect(150, 100, 20, 20)).setTo(0.0f);  // a hole
  const RegionDivision direct = DivideScene(depth, kLayers, kRadius);
  const RegionDivisionOptions options;
  const cv::Mat cells = CellMedianDepth(depth, options.cell_size_px);
  const RegionDivision shared = DivideScene(cells, depth.size(), kLayers, kRadius, options);
  EXPECT_EQ(cv::norm(direct.cell_depth_mm, shared.cell_depth_mm, cv::NORM_INF), 0.0);
  ASSERT_EQ(direct.blocks.size(), shared.blocks.size());
  for (std::size_t i = 0; i < direct.blocks.size(); ++i) {
    EXPECT_EQ(direct.blocks[i].layer_index, shared.blocks[i].layer_index);
    EXPECT_EQ(direct.blocks[i].bbox_px, shared.blocks[i].bbox_px);
    EXPECT_EQ(cv::countNonZero(direct.blocks[i].cells != shared.blocks[i].cells), 0);
  }
  // Cell depths of another grid are refused.
  EXPECT_THROW(DivideScene(cells, cv::Size(640, 480), kLayers, kRadius, options), Error);
  EXPECT_THROW(CellMedianDepth(cv::Mat(10, 10, CV_16U), 8), Error);
}

}  // namespace
}  // namespace layermod
