// SPDX-License-Identifier: MIT
#include "match/response_maps.h"

#include <gtest/gtest.h>

#include "match/spread.h"
#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(ResponseMapsTest, OrientationSimilarityIsTheDocumentedTable) {
  for (int label = 0; label < 8; ++label) {
    for (int scene_label = 0; scene_label < 8; ++scene_label) {
      EXPECT_EQ(OrientationSimilarity(label, scene_label),
                test::NaiveOrientationSimilarity(label, scene_label))
          << label << " vs " << scene_label;
    }
  }
  EXPECT_EQ(OrientationSimilarity(0, 7), 1);  // circular
}

TEST(ResponseMapsTest, BitmaskSimilarityTakesTheBestSetBit) {
  EXPECT_EQ(BitmaskSimilarity(3, 0), 0);
  EXPECT_EQ(BitmaskSimilarity(3, 0xFF), kMaxFeatureScore);
  EXPECT_EQ(BitmaskSimilarity(0, 1 << 7), 1);
  EXPECT_EQ(BitmaskSimilarity(0, (1 << 7) | (1 << 4)), 1);
  EXPECT_EQ(BitmaskSimilarity(5, (1 << 1) | (1 << 5)), kMaxFeatureScore);
  EXPECT_EQ(BitmaskSimilarity(2, 1 << 6), 0);
}

TEST(ResponseMapsTest, SimilarityRowIsTheBestSetBitForEveryBitmask) {
  for (int label = 0; label < kOrientationCount; ++label) {
    const std::uint8_t* row = BitmaskSimilarityRow(label);
    for (int bitmask = 0; bitmask < 256; ++bitmask) {
      int best = 0;
      for (int bit = 0; bit < kOrientationCount; ++bit) {
        if ((bitmask & (1 << bit)) != 0) best = std::max(best, OrientationSimilarity(label, bit));
      }
      ASSERT_EQ(row[bitmask], best) << "label " << label << ", bitmask " << bitmask;
    }
  }
}

TEST(ResponseMapsTest, EveryPathAgreesWithNaiveReference) {
  cv::RNG rng(11);
  for (const cv::Size size :
       {cv::Size(97, 61), cv::Size(640, 480), cv::Size(1, 3), cv::Size(33, 2), cv::Size(65, 1)}) {
    // Arbitrary bytes cover every bit combination spreading can produce.
    const cv::Mat spread = test::RandomBytes(size, rng);
    std::array<cv::Mat, 8> expected;
    for (int label = 0; label < 8; ++label) expected[label] = test::NaiveResponse(spread, label);
    for (SimdPath path : SupportedSimdPaths()) {
      const auto maps = ComputeResponseMaps(spread, path);
      for (int label = 0; label < 8; ++label) {
        ASSERT_EQ(maps[label].size(), size);
        EXPECT_EQ(cv::countNonZero(maps[label] != expected[label]), 0)
            << size << " label " << label << " path " << SimdPathName(path);
      }
    }
  }
}

TEST(ResponseMapsTest, SpreadQuantizedSceneGivesNaiveResponses) {
  cv::RNG rng(12);
  const cv::Mat quantized = test::RandomQuantized({101, 77}, 0.15, rng);
  for (int t : {1, 2, 4, 5, 8}) {
    const auto maps = ComputeResponseMaps(SpreadOrientations(quantized, t));
    const cv::Mat spread = test::NaiveSpread(quantized, t);
    for (int label = 0; label < 8; ++label) {
      EXPECT_EQ(cv::countNonZero(maps[label] != test::NaiveResponse(spread, label)), 0);
    }
  }
}

TEST(ResponseMapsTest, MapsKeepBlockSlackAfterEachRow) {
  const auto maps = ComputeResponseMaps(cv::Mat(5, 7, CV_8UC1, cv::Scalar(1)));
  for (const cv::Mat& map : maps) {
    EXPECT_GE(map.step[0], static_cast<std::size_t>(7 + kSimdBlock));
    // The slack of every row is addressable and zero.
    for (int row = 0; row < map.rows; ++row) {
      for (int column = 7; column < 7 + kSimdBlock; ++column) {
        ASSERT_EQ(map.ptr<std::uint8_t>(row)[column], 0) << "row " << row << ", column " << column;
      }
    }
  }
}

TEST(ResponseMapsTest, EmptyInEmptyOutAndBadTypeThrows) {
  for (const cv::Mat& map : ComputeResponseMaps(cv::Mat())) EXPECT_TRUE(map.empty());
  EXPECT_THROW(ComputeResponseMaps(cv::Mat::zeros(3, 3, CV_32FC1)), Error);
}

}  // namespace
}  // namespace layermod
