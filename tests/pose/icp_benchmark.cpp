// SPDX-License-Identifier: MIT
// Speed of point-to-plane ICP (RefinePoseIcp, default options) on the sample part at 800 mm in
// front of a wall: from a pose near the truth (a right pose candidate) and from one 25 mm and
// 15 degrees off (a wrong candidate, which runs every iteration). Run with
// --benchmark_repetitions=5 for medians.
#include <benchmark/benchmark.h>

#include "pose/icp.h"
#include "pose/pose_test_scene.h"

namespace layermod {
namespace {

void RefineFrom(benchmark::State& state, double angle_deg, const Eigen::Vector3d& shift_mm) {
  const Pose truth = test::SamplePose(800.0);
  const test::TestScene scene = test::RenderTestScene(truth);
  const Pose start = test::Perturb(truth, angle_deg, {1, 2, 0.5}, shift_mm);
  int iterations = 0;
  for (auto _ : state) {
    const IcpResult result =
        RefinePoseIcp(test::SampleRenderMesh(), test::VgaCamera(), scene.depth_mm, start);
    iterations = result.iterations;
    benchmark::DoNotOptimize(result.cam_from_model.t.data());
  }
  state.counters["iterations"] = iterations;
}

void BenchIcpNearTheTruth(benchmark::State& state) { RefineFrom(state, 4.0, {6.0, -5.0, 10.0}); }
BENCHMARK(BenchIcpNearTheTruth)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchIcpFarOff(benchmark::State& state) { RefineFrom(state, 15.0, {25.0, 0.0, 0.0}); }
BENCHMARK(BenchIcpFarOff)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace layermod

BENCHMARK_MAIN();
