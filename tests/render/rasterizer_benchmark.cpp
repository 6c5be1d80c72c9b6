// SPDX-License-Identifier: MIT
// Speed of the training rasterizer on a LineMOD-sized object: about 45k triangles, 200 mm across,
// Kinect camera. Self-contained (generated mesh). Run e.g. with --benchmark_repetitions=10.
#include <benchmark/benchmark.h>

#include <vector>

#include "render/rasterizer.h"
#include "render/test_meshes.h"

namespace layermod {
namespace {

// 2 * 160 * 141 = 45,120 triangles, close to the LineMOD can's 45,666.
RenderMesh DenseSphere() { return test::MakeUvSphere(100.0, 160, 142, {0.8f, 0.6f, 0.3f}); }

// Views from many directions so the tessellation is seen from varied angles.
std::vector<Pose> Poses(double distance_mm) {
  std::vector<Pose> poses;
  for (int i = 0; i < 16; ++i) {
    poses.push_back(test::LookAtPose(distance_mm, 23.0 * i, 41.0 * i, 17.0 * i));
  }
  return poses;
}

void RenderViews(benchmark::State& state, RenderWindow window) {
  const RenderMesh mesh = DenseSphere();
  const PinholeCamera camera = test::KinectCamera();
  const std::vector<Pose> poses = Poses(static_cast<double>(state.range(0)));
  RenderOptions options;
  options.window = window;
  std::size_t next = 0;
  for (auto _ : state) {
    RenderedView view = RenderView(mesh, camera, poses[next], options);
    benchmark::DoNotOptimize(view.depth_mm.data);
    next = (next + 1) % poses.size();
  }
  state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
}

void BM_RenderObjectWindow(benchmark::State& state) {
  RenderViews(state, RenderWindow::kObjectOnly);
}
void BM_RenderFullImage(benchmark::State& state) { RenderViews(state, RenderWindow::kFullImage); }

BENCHMARK(BM_RenderObjectWindow)->Arg(600)->Arg(800)->Arg(1200)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RenderFullImage)->Arg(800)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace layermod

BENCHMARK_MAIN();
