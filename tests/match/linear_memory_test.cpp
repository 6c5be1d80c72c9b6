// SPDX-License-Identifier: MIT
#include "match/linear_memory.h"

#include <gtest/gtest.h>

#include "match_test_util.h"
#include "util/error.h"

namespace layermod {
namespace {

// The documented layout, checked cell by cell: Memory(r, c)[gy * W + gx] = map(gy*T+r, gx*T+c).
void ExpectNaiveLayout(const cv::Mat& map, int t, const LinearMemory& linear) {
  const cv::Size grid((map.cols + t - 1) / t, (map.rows + t - 1) / t);
  ASSERT_EQ(linear.grid_size, grid);
  ASSERT_EQ(linear.spread_px, t);
  for (int r = 0; r < t; ++r) {
    for (int c = 0; c < t; ++c) {
      const std::uint8_t* memory = linear.Memory(r, c);
      for (int gy = 0; gy < grid.height; ++gy) {
        for (int gx = 0; gx < grid.width; ++gx) {
          const int y = gy * t + r;
          const int x = gx * t + c;
          const int expected = (x < map.cols && y < map.rows) ? map.at<std::uint8_t>(y, x) : 0;
          ASSERT_EQ(memory[gy * grid.width + gx], expected)
              << "T=" << t << " r=" << r << " c=" << c << " cell " << gx << "," << gy;
        }
      }
      for (int i = 0; i < kSimdBlock; ++i) ASSERT_EQ(memory[grid.area() + i], 0);
    }
  }
}

TEST(LinearMemoryTest, AgreesWithNaiveLayoutOnOddSizes) {
  cv::RNG rng(21);
  for (const cv::Size size :
       {cv::Size(97, 61), cv::Size(640, 480), cv::Size(1, 1), cv::Size(7, 3)}) {
    const cv::Mat map = test::RandomBytes(size, rng);
    for (int t : {1, 2, 4, 5, 8}) ExpectNaiveLayout(map, t, Linearize(map, t));
  }
}

TEST(LinearMemoryTest, LinearizesAllOrientationsOfAModality) {
  cv::RNG rng(22);
  std::array<cv::Mat, kOrientationCount> maps;
  for (cv::Mat& map : maps) map = test::RandomBytes({43, 29}, rng);
  const LinearMemories all = Linearize(maps, 5);
  EXPECT_EQ(all.grid_size, cv::Size(9, 6));
  EXPECT_EQ(all.spread_px, 5);
  for (int label = 0; label < kOrientationCount; ++label) {
    ExpectNaiveLayout(maps[label], 5, all.orientations[label]);
  }
  maps[3] = test::RandomBytes({44, 29}, rng);
  EXPECT_THROW(Linearize(maps, 5), Error);
}

TEST(LinearMemoryTest, ResponsesAtLeastFloorsAreThoseOfThePixelwiseMaximum) {
  cv::RNG rng(23);
  const cv::Mat map = test::RandomBytes({97, 61}, rng);
  cv::Mat floors = cv::Mat::zeros(map.size(), CV_8UC1);
  floors(cv::Rect(40, 10, 30, 51)).setTo(3);
  floors.at<std::uint8_t>(0, 0) = 200;
  floors.at<std::uint8_t>(60, 96) = 3;
  cv::Mat maximum;
  cv::max(map, floors, maximum);
  const LinearMemory linear = Linearize(map, 5);
  ExpectNaiveLayout(maximum, 5, ResponseAtLeast(linear, Linearize(floors, 5)));
  ExpectNaiveLayout(map, 5, linear);  // the original stays
  EXPECT_THROW(ResponseAtLeast(linear, Linearize(floors, 4)), Error);
  EXPECT_THROW(ResponseAtLeast(linear, Linearize(floors(cv::Rect(0, 0, 90, 61)), 5)), Error);
}

TEST(LinearMemoryTest, EmptyMapGivesEmptyGridAndBadArgumentsThrow) {
  const LinearMemory empty = Linearize(cv::Mat(), 4);
  EXPECT_EQ(empty.CellCount(), 0);
  EXPECT_THROW(Linearize(cv::Mat::zeros(4, 4, CV_8UC1), 0), Error);
  EXPECT_THROW(Linearize(cv::Mat::zeros(4, 4, CV_16UC1), 2), Error);
}

}  // namespace
}  // namespace layermod
