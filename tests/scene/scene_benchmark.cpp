// SPDX-License-Identifier: MIT
// The depth-only stages of Scene-Patch detection on a VGA depth map: a tilted table 700-1100 mm
// away with a dozen boxes on it, sensor noise and holes. Run with --benchmark_repetitions=5.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "features/depth_edges.h"
#include "scene/coarse_positioning.h"
#include "scene/region_division.h"

namespace layermod {
namespace {

const std::vector<double> kLayers = {627, 682, 736, 791, 846, 900, 955, 1009, 1064, 1118, 1173};
constexpr double kRadius = 55.0;
constexpr double kFocalPx = 572.4;

cv::Mat TableScene() {
  cv::RNG rng(99);
  cv::Mat depth(480, 640, CV_32F);
  for (int y = 0; y < depth.rows; ++y) {
    for (int x = 0; x < depth.cols; ++x) {
      depth.at<float>(y, x) = static_cast<float>(1100.0 - 0.8 * y + 0.05 * x);
    }
  }
  for (int i = 0; i < 12; ++i) {
    const cv::Rect box(rng.uniform(0, 560), rng.uniform(0, 400), rng.uniform(30, 80),
                       rng.uniform(30, 80));
    depth(box & cv::Rect(0, 0, 640, 480)) -= rng.uniform(40.0f, 120.0f);
  }
  cv::Mat noise(depth.size(), CV_32F);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, 1.5);
  depth += noise;
  for (int i = 0; i < 200; ++i) {
    cv::circle(depth, {rng.uniform(0, 640), rng.uniform(0, 480)}, rng.uniform(1, 4), cv::Scalar(0),
               cv::FILLED);
  }
  return depth;
}

void BenchCellMedianDepth(benchmark::State& state) {
  const cv::Mat depth = TableScene();
  for (auto _ : state) benchmark::DoNotOptimize(CellMedianDepth(depth, 8));
}
BENCHMARK(BenchCellMedianDepth)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchDivideSceneFromCells(benchmark::State& state) {
  const cv::Mat depth = TableScene();
  const cv::Mat cells = CellMedianDepth(depth, 8);
  for (auto _ : state) {
    benchmark::DoNotOptimize(DivideScene(cells, depth.size(), kLayers, kRadius));
  }
}
BENCHMARK(BenchDivideSceneFromCells)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchFillDepthHoles(benchmark::State& state) {
  const cv::Mat depth = TableScene();
  for (auto _ : state) benchmark::DoNotOptimize(FillDepthHolesFromFar(depth, 8));
}
BENCHMARK(BenchFillDepthHoles)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchDepthEdgeStrength(benchmark::State& state) {
  const cv::Mat depth = TableScene();
  for (auto _ : state) benchmark::DoNotOptimize(DepthEdgeStrength(depth));
}
BENCHMARK(BenchDepthEdgeStrength)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchPositionCoarsely(benchmark::State& state) {
  const cv::Mat depth = TableScene();
  const RegionDivision division = DivideScene(depth, kLayers, kRadius);
  const cv::Mat edges = DepthEdgeMaskFromStrength(DepthEdgeStrength(depth), 6.0f);
  const std::vector<LayerEdgeRange> ranges(kLayers.size(), LayerEdgeRange{150, 1300, true});
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        PositionCoarsely(division, depth, edges, kFocalPx, 2 * kRadius, ranges));
  }
}
BENCHMARK(BenchPositionCoarsely)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace layermod

BENCHMARK_MAIN();
