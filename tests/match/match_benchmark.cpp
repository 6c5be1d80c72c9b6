// SPDX-License-Identifier: MIT
// Scene preparation and template matching on a VGA scene with 2,000 two-level templates
// (63 + 63 features per level). Run with --benchmark_repetitions=5 for medians.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <array>

#include "match/candidate_area.h"
#include "match/matcher.h"
#include "match_test_util.h"

namespace layermod {
namespace {

constexpr int kTemplateCount = 2000;
constexpr int kTrueTemplates = 20;

TemplateLevel RandomLevel(int level, cv::Size box, cv::RNG& rng) {
  TemplateLevel result;
  result.pyramid_level = level;
  result.width = box.width;
  result.height = box.height;
  for (int m = 0; m < kModalityCount; ++m) {
    for (int i = 0; i < 63; ++i) {
      result.features.push_back({static_cast<std::int16_t>(rng.uniform(0, box.width)),
                                 static_cast<std::int16_t>(rng.uniform(0, box.height)),
                                 static_cast<std::uint8_t>(rng.uniform(0, 8)),
                                 static_cast<Modality>(m)});
    }
  }
  return result;
}

struct BenchData {
  test::TestScene scene;
  std::vector<TemplateRecord> templates;
  // 20 detection points as Scene-Patch coarse positioning yields them: a 5 x 4 grid, step 24 px,
  // over the block around one object (centred on a true template).
  std::vector<cv::Point> block_points;
  // 20 points scattered over the whole image (10 on true templates): the worst case.
  std::vector<cv::Point> scattered_points;
};

BenchData MakeData() {
  cv::RNG rng(1234);
  BenchData data;
  // Sparse labels, like the edges of a real scene.
  data.scene = test::RandomScene({640, 480}, 0.1, rng);
  for (std::uint32_t id = 0; id < kTemplateCount; ++id) {
    const cv::Size size(rng.uniform(70, 130), rng.uniform(70, 130));
    if (id < kTrueTemplates) {
      const cv::Rect box(rng.uniform(0, 640 - size.width), rng.uniform(0, 480 - size.height),
                         size.width, size.height);
      data.templates.push_back(test::TemplateFromScene(data.scene, box, 63, id, rng));
      data.templates.back().obj_id = static_cast<std::int32_t>(id);  // 20 distinct objects
      const cv::Point centre = box.tl() + cv::Point(size.width / 2, size.height / 2);
      if (id % 2 == 0) data.scattered_points.push_back(centre);
      if (id == 0) {
        for (int row = 0; row < 4; ++row) {
          for (int column = 0; column < 5; ++column) {
            data.block_points.push_back(centre + cv::Point(24 * column - 48, 24 * row - 36));
          }
        }
      }
      continue;
    }
    TemplateRecord record;
    record.id = id;
    record.levels = {RandomLevel(0, size, rng), RandomLevel(1, size / 2, rng)};
    data.templates.push_back(std::move(record));
  }
  while (data.scattered_points.size() < 20) {
    data.scattered_points.emplace_back(rng.uniform(0, 640), rng.uniform(0, 480));
  }
  return data;
}

const BenchData& Data() {
  static const BenchData data = MakeData();
  return data;
}

// state.range(0): worker threads (oneTBB's limit), to separate CPU cost from parallel speed-up.
tbb::global_control LimitThreads(const benchmark::State& state) {
  return tbb::global_control(tbb::global_control::max_allowed_parallelism,
                             static_cast<std::size_t>(state.range(0)));
}

void BenchPrepareScene(benchmark::State& state) {
  const BenchData& data = Data();
  const auto threads = LimitThreads(state);
  for (auto _ : state) {
    PreparedScene scene(data.scene.quantized, data.scene.spread_px);
    benchmark::DoNotOptimize(scene);
  }
}
BENCHMARK(BenchPrepareScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void RunMatch(benchmark::State& state, const std::vector<cv::Point>* points, SimdPath simd) {
  const BenchData& data = Data();
  const auto threads = LimitThreads(state);
  const PreparedScene scene(data.scene.quantized, data.scene.spread_px);
  MatchOptions options;
  options.simd = simd;
  std::size_t found = 0;
  for (auto _ : state) {
    const auto matches = MatchTemplates(scene, data.templates, options, points, 16);
    found = matches.size();
    benchmark::DoNotOptimize(matches.data());
  }
  state.counters["matches"] = static_cast<double>(found);
}

void BenchMatchFullSearch(benchmark::State& state) { RunMatch(state, nullptr, SimdPath::kAuto); }
BENCHMARK(BenchMatchFullSearch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchMatchFullSearchScalar(benchmark::State& state) {
  RunMatch(state, nullptr, SimdPath::kScalar);
}
BENCHMARK(BenchMatchFullSearchScalar)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchMatchBlockPoints(benchmark::State& state) {
  RunMatch(state, &Data().block_points, SimdPath::kAuto);
}
BENCHMARK(BenchMatchBlockPoints)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BenchMatchScatteredPoints(benchmark::State& state) {
  RunMatch(state, &Data().scattered_points, SimdPath::kAuto);
}
BENCHMARK(BenchMatchScatteredPoints)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The block points' search with the templates' facts worked out beforehand, as a detector does:
// without (0) and with (1) the top level's grid features. One thread.
void BenchMatchBlockPointsFacts(benchmark::State& state) {
  const BenchData& data = Data();
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const PreparedScene scene(data.scene.quantized, data.scene.spread_px);
  const std::vector<TemplateFacts> facts = TemplateFactsOf(
      data.templates,
      state.range(0) == 1 ? std::span<const int>(data.scene.spread_px) : std::span<const int>());
  const TemplateSearch search{data.templates, &data.block_points, {}, nullptr, facts};
  std::size_t found = 0;
  for (auto _ : state) {
    const auto matches =
        MatchTemplateGroups(scene, std::span<const TemplateSearch>(&search, 1), {}, 16);
    found = matches.size();
    benchmark::DoNotOptimize(matches.data());
  }
  state.counters["matches"] = static_cast<double>(found);
}
BENCHMARK(BenchMatchBlockPointsFacts)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The candidate area of one depth layer's kept points as Scene-Patch coarse positioning yields
// them: every 8 px over two 200 x 150 px blocks (about 950 points), within 8 px, for the cell
// spans of both pyramid levels; then every phase's near cells of 2,000 anchors.
void BenchCandidateArea(benchmark::State& state) {
  std::vector<cv::Point> points;
  for (const cv::Point corner : {cv::Point(100, 80), cv::Point(320, 260)}) {
    for (int y = 0; y < 150; y += 8) {
      for (int x = 0; x < 200; x += 8) points.push_back(corner + cv::Point(x, y));
    }
  }
  const std::array<int, 2> spans = {8, 16};
  std::vector<GridRowSpan> cells;
  for (auto _ : state) {
    const CandidateArea area = MakeCandidateArea(points, 8, cv::Size(640, 480), spans);
    for (int anchor = 0; anchor < kTemplateCount; ++anchor) {
      NearCells(16, cv::Point(anchor % 61, anchor % 53), cv::Size(40, 30), area, cells);
      benchmark::DoNotOptimize(cells.data());
    }
  }
  state.counters["points"] = static_cast<double>(points.size());
}
BENCHMARK(BenchCandidateArea)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace layermod

BENCHMARK_MAIN();
