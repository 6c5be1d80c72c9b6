// SPDX-License-Identifier: MIT
// Many frames through the public API with the archive loaded once: the wall time of a Detect
// call against the detector's own stage total (Timings::total_ms), i.e. what the facade adds
// (16-bit depth conversion, result conversion). Run with --benchmark_repetitions=5.
#include <benchmark/benchmark.h>

#include <layermod/detector.h>

#include "api_fixture.h"

namespace layermod::api {
namespace {

void DetectFrames(benchmark::State& state, bool sixteen_bit) {
  const test::ApiSample& sample = test::Sample();
  const Detector detector({Archive::Load(sample.archive_path)});
  std::vector<Capture> frames;
  for (const test::SampleFrame& frame : sample.frames) {
    Capture capture = frame.capture;
    if (sixteen_bit) capture.depth.convertTo(capture.depth, CV_16U);
    frames.push_back(capture);
  }
  double stage_total_ms = 0.0;
  std::size_t calls = 0;
  for (auto _ : state) {
    const DetectionResult result = detector.Detect(frames[calls % frames.size()]);
    stage_total_ms += result.timings.total_ms;
    ++calls;
    benchmark::DoNotOptimize(result.detections.data());
  }
  state.counters["stage_total_ms"] = stage_total_ms / static_cast<double>(calls);
}

BENCHMARK_CAPTURE(DetectFrames, float_depth, false)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(DetectFrames, uint16_depth, true)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace layermod::api

BENCHMARK_MAIN();
