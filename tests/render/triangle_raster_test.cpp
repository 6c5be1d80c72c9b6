// SPDX-License-Identifier: MIT
#include "render/triangle_raster.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

namespace layermod::render_internal {
namespace {

ScreenVertex AtPixel(double u, double v, float inv_z = 0.001f) {
  ScreenVertex vertex;
  vertex.x = static_cast<std::int32_t>(std::lround((u + kGuardBandPx) * kSubpixelScale));
  vertex.y = static_cast<std::int32_t>(std::lround((v + kGuardBandPx) * kSubpixelScale));
  vertex.inv_z = inv_z;
  return vertex;
}

// Counts how often each pixel of a 100 x 100 window is drawn.
struct CoverageCounter {
  PixelWindow window{0, 0, 99, 99};
  std::vector<int> counts = std::vector<int>(100 * 100, 0);

  void Draw(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
    RasterizeTriangle(a, b, c, window,
                      [&](int x, int y, float, bool inside) { counts[y * 100 + x] += inside; });
  }
  int at(int x, int y) const { return counts[y * 100 + x]; }
};

TEST(TriangleRasterTest, SharedEdgesCoverEveryPixelExactlyOnce) {
  // A grid over [10, 90]^2 whose inner vertices are jittered, often onto pixel centres or
  // half-pixel positions, so many edges pass exactly through pixel centres.
  constexpr int kCells = 10;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> half_pixels(-3, 3);
  std::uniform_real_distribution<double> fraction(-0.5, 0.5);
  std::vector<std::vector<ScreenVertex>> grid(kCells + 1, std::vector<ScreenVertex>(kCells + 1));
  for (int i = 0; i <= kCells; ++i) {
    for (int j = 0; j <= kCells; ++j) {
      double u = 10.0 + 8.0 * i;
      double v = 10.0 + 8.0 * j;
      const bool border = i == 0 || j == 0 || i == kCells || j == kCells;
      if (!border) {
        u += 0.5 * half_pixels(random) + ((i + j) % 3 == 0 ? fraction(random) : 0.0);
        v += 0.5 * half_pixels(random);
      }
      grid[i][j] = AtPixel(u, v);
    }
  }
  CoverageCounter coverage;
  for (int i = 0; i < kCells; ++i) {
    for (int j = 0; j < kCells; ++j) {
      // Alternate the diagonal and the winding: neither may matter.
      if ((i + j) % 2 == 0) {
        coverage.Draw(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1]);
        coverage.Draw(grid[i][j], grid[i][j + 1], grid[i + 1][j + 1]);
      } else {
        coverage.Draw(grid[i][j], grid[i + 1][j], grid[i][j + 1]);
        coverage.Draw(grid[i + 1][j + 1], grid[i][j + 1], grid[i + 1][j]);
      }
    }
  }
  // Top-left rule on the outer square: columns/rows 10..89 are covered.
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const bool inside = x >= 10 && x < 90 && y >= 10 && y < 90;
      ASSERT_EQ(coverage.at(x, y), inside ? 1 : 0) << "pixel " << x << ", " << y;
    }
  }
}

TEST(TriangleRasterTest, FanAroundPixelCentreDrawsCentreOnce) {
  const ScreenVertex centre = AtPixel(50, 50);
  constexpr int kSpokes = 12;
  std::vector<ScreenVertex> rim;
  for (int k = 0; k < kSpokes; ++k) {
    const double angle = 2.0 * 3.14159265358979 * k / kSpokes;
    rim.push_back(
        AtPixel(std::round(50 + 20 * std::cos(angle)), std::round(50 + 20 * std::sin(angle))));
  }
  CoverageCounter coverage;
  for (int k = 0; k < kSpokes; ++k) coverage.Draw(centre, rim[k], rim[(k + 1) % kSpokes]);
  EXPECT_EQ(coverage.at(50, 50), 1);
  for (const int count : coverage.counts) ASSERT_LE(count, 1);
}

std::vector<std::tuple<int, int, float>> Fragments(const ScreenVertex& a, const ScreenVertex& b,
                                                   const ScreenVertex& c,
                                                   const PixelWindow& window) {
  std::vector<std::tuple<int, int, float>> fragments;
  RasterizeTriangle(a, b, c, window, [&](int x, int y, float inv_z, bool inside) {
    if (inside) fragments.emplace_back(x, y, inv_z);
  });
  return fragments;
}

TEST(TriangleRasterTest, WindingDoesNotChangeCoverage) {
  const ScreenVertex a = AtPixel(3.3, 4.1, 0.01f);
  const ScreenVertex b = AtPixel(40.7, 12.0, 0.02f);
  const ScreenVertex c = AtPixel(17.0, 33.5, 0.03f);
  const PixelWindow window{0, 0, 63, 63};
  const auto forward = Fragments(a, b, c, window);
  const auto backward = Fragments(a, c, b, window);
  EXPECT_GT(forward.size(), 300u);
  ASSERT_EQ(forward.size(), backward.size());
  for (std::size_t i = 0; i < forward.size(); ++i) {
    EXPECT_EQ(std::get<0>(forward[i]), std::get<0>(backward[i]));
    EXPECT_EQ(std::get<1>(forward[i]), std::get<1>(backward[i]));
    EXPECT_NEAR(std::get<2>(forward[i]), std::get<2>(backward[i]), 1e-7);
  }
}

TEST(TriangleRasterTest, SinglePixelPathMatchesTheGeneralPath) {
  // Random small triangles around one pixel centre, of both windings, some with corners or edges
  // exactly on it: the shortcut must give the same coverage and depth as the general loop.
  std::mt19937 random(11);
  std::uniform_int_distribution<int> offset(-3, 3);
  std::uniform_real_distribution<float> depth(0.001f, 0.002f);
  const PixelWindow window{0, 0, 63, 63};
  int drawn = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto corner = [&] {
      return AtPixel(20 + 0.25 * offset(random), 30 + 0.25 * offset(random), depth(random));
    };
    const ScreenVertex a = corner(), b = corner(), c = corner();
    const PixelWindow box = TrianglePixelBox(a, b, c, window);
    if (box.empty() || box.x0 != box.x1 || box.y0 != box.y1) continue;
    const auto general = Fragments(a, b, c, window);
    std::vector<std::tuple<int, int, float>> single;
    RasterizeTriangleAtPixel(a, b, c, box.x0, box.y0, [&](int x, int y, float inv_z, bool inside) {
      if (inside) single.emplace_back(x, y, inv_z);
    });
    ASSERT_EQ(general, single) << "trial " << trial;
    drawn += static_cast<int>(single.size());
  }
  EXPECT_GT(drawn, 100);
}

TEST(TriangleRasterTest, DegenerateAndSubPixelTrianglesDrawNothing) {
  const PixelWindow window{0, 0, 63, 63};
  EXPECT_TRUE(Fragments(AtPixel(1, 1), AtPixel(10, 10), AtPixel(20, 20), window).empty());
  EXPECT_TRUE(Fragments(AtPixel(5.1, 5.1), AtPixel(5.9, 5.2), AtPixel(5.5, 5.8), window).empty());
  // A tiny triangle around a pixel centre does draw it.
  EXPECT_EQ(Fragments(AtPixel(4.9, 4.9), AtPixel(5.2, 4.9), AtPixel(5.0, 5.2), window).size(), 1u);
}

TEST(TriangleRasterTest, DrawsOnlyInsideTheWindow) {
  const PixelWindow window{10, 20, 29, 34};
  const auto fragments = Fragments(AtPixel(-50, -40), AtPixel(90, 0), AtPixel(0, 95), window);
  EXPECT_EQ(fragments.size(), static_cast<std::size_t>(window.width() * window.height()));
  for (const auto& [x, y, inv_z] : fragments) {
    EXPECT_TRUE(x >= window.x0 && x <= window.x1 && y >= window.y0 && y <= window.y1);
  }
}

TEST(TriangleRasterTest, InverseDepthIsLinearInScreenSpace) {
  // inv_z = 0.001 + 0.0001 u + 0.00005 v at the vertices; must hold at every pixel centre.
  const auto plane = [](double u, double v) { return 0.001 + 0.0001 * u + 0.00005 * v; };
  const auto vertex = [&](double u, double v) {
    return AtPixel(u, v, static_cast<float>(plane(u, v)));
  };
  const auto fragments =
      Fragments(vertex(2, 3), vertex(60, 8), vertex(25, 61), PixelWindow{0, 0, 63, 63});
  ASSERT_GT(fragments.size(), 1000u);
  for (const auto& [x, y, inv_z] : fragments) EXPECT_NEAR(inv_z, plane(x, y), 1e-8);
}

}  // namespace
}  // namespace layermod::render_internal
