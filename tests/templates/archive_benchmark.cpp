// SPDX-License-Identifier: MIT
// Archive write/load speed and size for a realistic template count (the load target: 20k
// templates in well under a second). On a busy machine run
//   layermod_archive_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// and read the "_min" rows.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "archive_fixtures.h"
#include "templates/archive.h"
#include "templates/archive_tables.h"
#include "util/atomic_file.h"

namespace layermod {
namespace {
namespace fs = std::filesystem;

// With --benchmark_repetitions=N, the fastest run is the best estimate on a busy machine.
double Fastest(const std::vector<double>& times) {
  return *std::min_element(times.begin(), times.end());
}

// 20,000 templates x 2 levels x 126 features (63 per modality at each level).
const TemplateArchive& BigArchive() {
  static const TemplateArchive archive = [] {
    test::SyntheticArchiveOptions options;
    options.obj_ids = {1};
    options.layers_per_object = {10};
    options.views_per_layer = 2000;
    options.levels = 2;
    options.color_features = 63;
    options.normal_features = 63;
    options.halve_features_per_level = false;
    options.weak_every = 0;
    return test::MakeSyntheticArchive(options);
  }();
  return archive;
}

fs::path BenchPath() {
  return fs::temp_directory_path() /
         ("layermod-archive-bench-" + std::to_string(::getpid()) + ".layermod");
}

void BM_WriteArchive(benchmark::State& state) {
  const TemplateArchive& archive = BigArchive();
  const fs::path path = BenchPath();
  for (auto _ : state) WriteArchive(path, archive);
  state.counters["templates"] = static_cast<double>(archive.templates().size());
  state.counters["file_MB"] = static_cast<double>(fs::file_size(path)) / 1e6;
  fs::remove(path);
}
BENCHMARK(BM_WriteArchive)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", Fastest);

void BM_ReadArchive(benchmark::State& state) {
  const fs::path path = BenchPath();
  WriteArchive(path, BigArchive());
  for (auto _ : state) {
    const TemplateArchive loaded = ReadArchive(path);
    benchmark::DoNotOptimize(loaded.templates().data());
  }
  state.counters["file_MB"] = static_cast<double>(fs::file_size(path)) / 1e6;
  fs::remove(path);
}
BENCHMARK(BM_ReadArchive)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", Fastest);

// Decoding alone, without the disk read.
void BM_ReadArchiveBytes(benchmark::State& state) {
  const fs::path path = BenchPath();
  WriteArchive(path, BigArchive());
  const std::string bytes = ReadFileBytes(path);
  fs::remove(path);
  for (auto _ : state) {
    const TemplateArchive loaded = ReadArchiveBytes(bytes, "bench.layermod");
    benchmark::DoNotOptimize(loaded.templates().data());
  }
}
BENCHMARK(BM_ReadArchiveBytes)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->ComputeStatistics("min", Fastest);

// Table decoding and validation alone, without the container.
void BM_DecodeTables(benchmark::State& state) {
  const EncodedTables tables = EncodeTables(BigArchive().templates());
  for (auto _ : state) {
    const std::vector<TemplateRecord> decoded =
        DecodeTables(tables.templates, tables.features, BigArchive().manifest());
    benchmark::DoNotOptimize(decoded.data());
  }
}
BENCHMARK(BM_DecodeTables)->Unit(benchmark::kMillisecond)->ComputeStatistics("min", Fastest);

}  // namespace
}  // namespace layermod

BENCHMARK_MAIN();
