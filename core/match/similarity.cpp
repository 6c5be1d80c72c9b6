// SPDX-License-Identifier: MIT
#include "match/similarity.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "match/response_maps.h"
#include "match/spread.h"
#include "util/error.h"

namespace layermod {
namespace {

// A stretch of consecutive positions: for every feature, `length` source bytes starting at the
// feature's base pointer + source_offset are added to the buffer at buffer_offset.
struct Run {
  int buffer_offset = 0;
  std::ptrdiff_t source_offset = 0;
  int length = 0;
};

bool UseEightBits(Accumulator accumulator, int feature_count) {
  if (accumulator == Accumulator::k8Bit && feature_count > kMax8BitFeatures) {
    throw Error("the 8-bit similarity path holds at most " + std::to_string(kMax8BitFeatures) +
                " features, the template has " + std::to_string(feature_count));
  }
  if (accumulator == Accumulator::kAuto) return feature_count <= kMax8BitFeatures;
  return accumulator == Accumulator::k8Bit;
}

// Sums the features' source bytes over the runs. `buffer_size` must cover every run's block
// rounding (RoundUpToSimdBlock), and the runs' rounded stretches must not overlap.
// The sums go to `sums` (resized to buffer_size); refinement calls this thousands of times per
// frame, so the buffers are reused rather than allocated per call.
void AccumulateRuns(const std::vector<const std::uint8_t*>& sources, const std::vector<Run>& runs,
                    int buffer_size, const SimilarityOptions& options,
                    std::vector<std::uint16_t>& sums) {
  const SimdPath path = ResolveSimdPath(options.simd);
  const int count = static_cast<int>(sources.size());
  const bool eight_bit = UseEightBits(options.accumulator, count);
  if (eight_bit && count > 0) {
    sums.resize(static_cast<std::size_t>(buffer_size));  // one chunk, copied over whole below
  } else {
    sums.assign(static_cast<std::size_t>(buffer_size), 0);
  }
  thread_local std::vector<std::uint8_t> partial;
  partial.resize(static_cast<std::size_t>(buffer_size));
  const int chunk = eight_bit ? std::max(count, 1) : kMax8BitFeatures;
  for (int first = 0; first < count; first += chunk) {
    std::fill(partial.begin(), partial.end(), 0);
    const int last = std::min(count, first + chunk);
    for (const Run& run : runs) {
      AddRowsSaturateU8(partial.data() + run.buffer_offset, sources.data() + first, last - first,
                        run.source_offset, run.length, path);
    }
    if (eight_bit) {
      std::copy(partial.begin(), partial.end(), sums.begin());
      continue;
    }
    for (const Run& run : runs) {
      AddSaturateWidenU16(sums.data() + run.buffer_offset, partial.data() + run.buffer_offset,
                          run.length, path);
    }
  }
}

// Runs closer than this many cells are merged: computing a short gap costs less than another
// block-rounded run (and rounded runs must not overlap anyway).
constexpr int kMergeGapCells = kSimdBlock;

// Spans clipped to the valid cells, empty ones dropped, sorted by row then first column.
std::vector<GridRowSpan> ClipAndSortSpans(std::span<const GridRowSpan> spans,
                                          const cv::Size& cells) {
  std::vector<GridRowSpan> clipped;
  clipped.reserve(spans.size());
  for (GridRowSpan span : spans) {
    span.first_column = std::max(span.first_column, 0);
    span.last_column = std::min(span.last_column, cells.width - 1);
    if (span.row < 0 || span.row >= cells.height || span.first_column > span.last_column) continue;
    clipped.push_back(span);
  }
  std::sort(clipped.begin(), clipped.end(), [](const GridRowSpan& a, const GridRowSpan& b) {
    return std::tie(a.row, a.first_column) < std::tie(b.row, b.first_column);
  });
  return clipped;
}

// The spans' cells in row-major index space (stride grid_width), as runs. Consecutive spans are
// merged when close, across row ends too: the cells in between (including those past a row's
// last valid column) are computed in passing and never read back, and one long run beats many
// short ones. Runs are packed one after the other into the sums buffer, each rounded up to whole
// SIMD blocks, so the buffer is only as long as what is scored. `spans` must be sorted
// (ClipAndSortSpans).
void GridRuns(std::span<const GridRowSpan> spans, int grid_width, std::vector<Run>& runs) {
  runs.clear();
  int buffer_end = 0;
  for (const GridRowSpan& span : spans) {
    const int start = span.row * grid_width + span.first_column;
    const int end = span.row * grid_width + span.last_column + 1;
    if (!runs.empty()) {
      Run& last = runs.back();
      const auto last_start = static_cast<int>(last.source_offset);
      if (start < last_start + RoundUpToSimdBlock(last.length) + kMergeGapCells) {
        last.length = std::max(last.length, end - last_start);
        buffer_end = last.buffer_offset + RoundUpToSimdBlock(last.length);
        continue;
      }
    }
    runs.push_back(Run{buffer_end, start, end - start});
    buffer_end += RoundUpToSimdBlock(end - start);
  }
}

// Appends each span's cells from `packed`, the buffer GridRuns(spans, grid_width) laid out, to
// `sums`, span after span.
void CopySpanSums(std::span<const GridRowSpan> spans, const std::vector<Run>& runs, int grid_width,
                  const std::vector<std::uint16_t>& packed, std::vector<std::uint16_t>& sums) {
  std::size_t run = 0;
  for (const GridRowSpan& span : spans) {
    const int start = span.row * grid_width + span.first_column;
    while (start >= runs[run].source_offset + runs[run].length) ++run;
    const auto first = packed.begin() + runs[run].buffer_offset + start -
                       static_cast<std::ptrdiff_t>(runs[run].source_offset);
    sums.insert(sums.end(), first, first + (span.last_column - span.first_column + 1));
  }
}

// The non-zero stretches of a mask, as spans.
std::vector<GridRowSpan> MaskSpans(const cv::Mat& mask) {
  std::vector<GridRowSpan> spans;
  for (int gy = 0; gy < mask.rows; ++gy) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(gy);
    for (int gx = 0; gx < mask.cols; ++gx) {
      if (row[gx] == 0) continue;
      const int first = gx;
      while (gx + 1 < mask.cols && row[gx + 1] != 0) ++gx;
      spans.push_back({gy, first, gx});
    }
  }
  return spans;
}

template <typename Fn>
void ForEachUsableFeature(const TemplateLevel& level, const SceneLevel& scene, Fn&& fn) {
  for (const Feature& feature : level.features) {
    if (scene.HasModality(feature.modality)) fn(feature);
  }
}

// The row step shared by the response maps the features read; they must keep block slack.
std::size_t CommonResponseStep(const TemplateLevel& level, const SceneLevel& scene) {
  std::size_t step = 0;
  ForEachUsableFeature(level, scene, [&](const Feature& feature) {
    const cv::Mat& map = scene.responses[ModalityIndex(feature.modality)][feature.label];
    if (step != 0 && map.step[0] != step) {
      throw Error("the scene's response maps do not share one row step");
    }
    step = map.step[0];
  });
  if (step < static_cast<std::size_t>(scene.size_px.width) + kSimdBlock) {
    throw Error("the scene's response maps lack the SIMD block slack (use ComputeResponseMaps)");
  }
  return step;
}

// x / T for 0 <= x <= 32767 (feature coordinates are int16) and 1 <= T <= kMaxSpreadPx, by a
// multiply and shift: a hardware division per feature and coordinate used to cost more than
// setting up the rest of a template's grid pass. Exact: with magic = floor(2^20 / T) + 1 the
// error term x * (magic * T - 2^20) / 2^20 stays below 1 / T because x * T < 2^20.
class SpreadDivider {
 public:
  explicit SpreadDivider(int spread_px)
      : magic_((1u << 20) / static_cast<std::uint32_t>(spread_px) + 1) {}
  int Quotient(int x) const {
    return static_cast<int>((static_cast<std::uint32_t>(x) * magic_) >> 20);
  }

 private:
  std::uint32_t magic_;
};

// Cells per grid row; the same for every present modality (they share the level's size).
int GridWidth(const SceneLevel& scene) {
  for (const LinearMemories& memories : scene.memories) {
    if (memories.grid_size.width > 0) return memories.grid_size.width;
  }
  return 0;
}

std::string InvalidFeatureMessage(const TemplateLevel& level, const Feature& feature) {
  return "template level " + std::to_string(level.pyramid_level) + " has an invalid feature (x " +
         std::to_string(feature.x) + ", y " + std::to_string(feature.y) + ", label " +
         std::to_string(feature.label) + ", modality " +
         std::to_string(ModalityIndex(feature.modality)) + ")";
}

cv::Rect ValidRect(const cv::Size& extent, const cv::Size& scene_size_px) {
  const int columns = scene_size_px.width - extent.width + 1;
  const int rows = scene_size_px.height - extent.height + 1;
  if (columns <= 0 || rows <= 0) return {};
  return {0, 0, columns, rows};
}

// Where each usable feature's responses for the grid's first cell lie, in feature order: from
// the summary's grid features when it has them, else worked out from the features.
void MemorySources(const TemplateLevel& level, const SceneLevel& scene,
                   const TemplateLevelSummary& summary, int grid_width,
                   std::vector<const std::uint8_t*>& sources) {
  sources.clear();
  const auto rows = static_cast<std::size_t>(MemoryRowCount(scene.spread_px));
  if (!summary.grid_features.empty() && summary.grid_features.size() == level.features.size() &&
      scene.memory_rows.size() == rows) {
    sources.resize(static_cast<std::size_t>(summary.usable_features));
    std::size_t next = 0;
    for (const GridFeature& feature : summary.grid_features) {
      const std::uint8_t* row = scene.memory_rows[feature.memory_row];
      if (row == nullptr) continue;  // a modality the scene lacks
      sources[next++] =
          row + static_cast<std::ptrdiff_t>(feature.cell_y) * grid_width + feature.cell_x;
    }
    if (next != sources.size()) {
      throw Error("grid features: the summary was made for another scene level");
    }
    return;
  }
  const SpreadDivider divider(scene.spread_px);
  ForEachUsableFeature(level, scene, [&](const Feature& f) {
    const LinearMemory& memory = scene.memories[ModalityIndex(f.modality)].orientations[f.label];
    const int qx = divider.Quotient(f.x);
    const int qy = divider.Quotient(f.y);
    sources.push_back(memory.Memory(f.y - qy * scene.spread_px, f.x - qx * scene.spread_px) +
                      static_cast<std::ptrdiff_t>(qy) * grid_width + qx);
  });
}

// The grid pass proper on `wanted` (spans of a summarized template level, clipped to its cells,
// sorted, not overlapping): the sums of their cells, span after span, into `sums`.
void ScoreCells(const TemplateLevel& level, const SceneLevel& scene,
                const TemplateLevelSummary& summary, std::span<const GridRowSpan> wanted,
                const SimilarityOptions& options, std::vector<std::uint16_t>& sums) {
  if (!scene.linearized) {
    throw Error("the scene level has no linear memories (use LinearizeSceneLevel)");
  }
  sums.clear();
  std::size_t cell_count = 0;
  for (const GridRowSpan& span : wanted) cell_count += span.last_column - span.first_column + 1;
  if (cell_count == 0 || summary.usable_features == 0) {
    sums.assign(cell_count, 0);
    return;
  }
  const int grid_width = GridWidth(scene);
  // Reused per thread: one template after another, allocating nothing.
  thread_local std::vector<Run> runs;
  GridRuns(wanted, grid_width, runs);
  thread_local std::vector<const std::uint8_t*> sources;
  MemorySources(level, scene, summary, grid_width, sources);
  const int buffer_size = runs.back().buffer_offset + RoundUpToSimdBlock(runs.back().length);
  thread_local std::vector<std::uint16_t> packed;
  AccumulateRuns(sources, runs, buffer_size, options, packed);
  sums.reserve(cell_count);
  CopySpanSums(wanted, runs, grid_width, packed, sums);
}

// ScoreCells laid out as the grid image.
GridSimilarity ScoreGrid(const TemplateLevel& level, const SceneLevel& scene,
                         const TemplateLevelSummary& summary, std::span<const GridRowSpan> spans,
                         const SimilarityOptions& options) {
  GridSimilarity result;
  result.spread_px = scene.spread_px;
  result.feature_count = summary.usable_features;
  const cv::Size cells = GridPositionCount(summary.extent, scene);
  result.sums = cv::Mat::zeros(cells, CV_16UC1);
  if (cells.empty() || result.feature_count == 0) return result;
  const std::vector<GridRowSpan> wanted = ClipAndSortSpans(spans, cells);
  thread_local std::vector<std::uint16_t> sums;
  ScoreCells(level, scene, summary, wanted, options, sums);
  auto next = sums.begin();
  for (const GridRowSpan& span : wanted) {
    const int length = span.last_column - span.first_column + 1;
    std::copy_n(next, length, result.sums.ptr<std::uint16_t>(span.row) + span.first_column);
    next += length;
  }
  return result;
}

}  // namespace

void CheckTemplateLevel(const TemplateLevel& level) {
  if (level.features.size() > static_cast<std::size_t>(kMaxTemplateFeatures)) {
    throw Error("template level " + std::to_string(level.pyramid_level) + " has " +
                std::to_string(level.features.size()) + " features, more than " +
                std::to_string(kMaxTemplateFeatures));
  }
  for (const Feature& feature : level.features) {
    if (feature.x < 0 || feature.y < 0 || feature.label >= kOrientationCount ||
        ModalityIndex(feature.modality) >= kModalityCount) {
      throw Error(InvalidFeatureMessage(level, feature));
    }
  }
}

// `level`'s features as GridFeatures for spread `spread_px`; empty when one lies more than 255
// cells out.
std::vector<GridFeature> GridFeaturesOf(const TemplateLevel& level, int spread_px) {
  std::vector<GridFeature> grid;
  grid.reserve(level.features.size());
  for (const Feature& feature : level.features) {
    const int cell_x = feature.x / spread_px;
    const int cell_y = feature.y / spread_px;
    constexpr int kLastCell = std::numeric_limits<std::uint8_t>::max();  // GridFeature's cells
    if (cell_x > kLastCell || cell_y > kLastCell) return {};
    grid.push_back({static_cast<std::uint16_t>(MemoryRowKey(
                        ModalityIndex(feature.modality), feature.label,
                        feature.x - cell_x * spread_px, feature.y - cell_y * spread_px, spread_px)),
                    static_cast<std::uint8_t>(cell_x), static_cast<std::uint8_t>(cell_y)});
  }
  return grid;
}

TemplateLevelFacts LevelFacts(const TemplateLevel& level, int grid_spread_px) {
  if (level.features.size() > static_cast<std::size_t>(kMaxTemplateFeatures)) {
    CheckTemplateLevel(level);  // throws with the message
  }
  TemplateLevelFacts facts;
  facts.extent = cv::Size(std::max(level.width, 0), std::max(level.height, 0));
  for (const Feature& feature : level.features) {
    const int modality = ModalityIndex(feature.modality);
    if (feature.x < 0 || feature.y < 0 || feature.label >= kOrientationCount ||
        modality >= kModalityCount) {
      throw Error(InvalidFeatureMessage(level, feature));
    }
    facts.extent.width = std::max(facts.extent.width, feature.x + 1);
    facts.extent.height = std::max(facts.extent.height, feature.y + 1);
    ++facts.features_by_modality[static_cast<std::size_t>(modality)];
  }
  if (grid_spread_px != 0) {
    if (grid_spread_px < 1 || grid_spread_px > kMaxSpreadPx) {
      throw Error("grid features: spread T = " + std::to_string(grid_spread_px) +
                  " is outside 1.." + std::to_string(kMaxSpreadPx));
    }
    facts.grid_features = GridFeaturesOf(level, grid_spread_px);
    if (!facts.grid_features.empty()) facts.grid_spread_px = grid_spread_px;
  }
  return facts;
}

TemplateLevelSummary SummarizeFacts(const TemplateLevelFacts& facts, const SceneLevel& scene) {
  TemplateLevelSummary summary;
  summary.extent = facts.extent;
  for (std::size_t m = 0; m < facts.features_by_modality.size(); ++m) {
    if (scene.present[m]) summary.usable_features += facts.features_by_modality[m];
  }
  if (facts.grid_spread_px == scene.spread_px && !scene.memory_rows.empty()) {
    summary.grid_features = facts.grid_features;
  }
  return summary;
}

TemplateLevelSummary SummarizeTemplateLevel(const TemplateLevel& level, const SceneLevel& scene) {
  return SummarizeFacts(LevelFacts(level), scene);
}

cv::Size TemplateExtent(const TemplateLevel& level) {
  cv::Size extent(std::max(level.width, 0), std::max(level.height, 0));
  for (const Feature& feature : level.features) {
    extent.width = std::max(extent.width, feature.x + 1);
    extent.height = std::max(extent.height, feature.y + 1);
  }
  return extent;
}

cv::Rect ValidPositions(const TemplateLevel& level, const cv::Size& scene_size_px) {
  return ValidRect(TemplateExtent(level), scene_size_px);
}

int UsableFeatureCount(const TemplateLevel& level, const SceneLevel& scene) {
  int count = 0;
  ForEachUsableFeature(level, scene, [&](const Feature&) { ++count; });
  return count;
}

float SimilarityPercent(int sum, int feature_count) {
  if (feature_count <= 0) return 0.0f;
  return 100.0f * static_cast<float>(sum) / static_cast<float>(kMaxFeatureScore * feature_count);
}

int MinimumSumForPercent(float percent, int feature_count) {
  const int max_sum = kMaxFeatureScore * std::max(feature_count, 0);
  int sum = std::clamp(static_cast<int>(std::ceil(percent * static_cast<float>(max_sum) / 100.0f)),
                       0, max_sum + 1);
  // Float rounding may put the estimate one off either way; settle it with the percent itself.
  while (sum > 0 && SimilarityPercent(sum - 1, feature_count) >= percent) --sum;
  while (sum <= max_sum && SimilarityPercent(sum, feature_count) < percent) ++sum;
  return sum;
}

cv::Size GridPositionCount(const TemplateLevel& level, const SceneLevel& scene) {
  return GridPositionCount(TemplateExtent(level), scene);
}

cv::Size GridPositionCount(const cv::Size& template_extent, const SceneLevel& scene) {
  const cv::Rect valid = ValidRect(template_extent, scene.size_px);
  if (valid.empty() || scene.spread_px < 1) return {};
  return {(valid.width - 1) / scene.spread_px + 1, (valid.height - 1) / scene.spread_px + 1};
}

GridSimilarity ComputeGridSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                     const cv::Mat& cell_mask, const SimilarityOptions& options) {
  const TemplateLevelSummary summary = SummarizeTemplateLevel(level, scene);
  if (cell_mask.empty()) return ComputeGridSimilarity(level, scene, summary, options);
  if (cell_mask.size() != GridPositionCount(summary.extent, scene) || cell_mask.type() != CV_8UC1) {
    throw Error("grid similarity mask must be CV_8UC1 of the grid position count");
  }
  return ScoreGrid(level, scene, summary, MaskSpans(cell_mask), options);
}

std::vector<GridRowSpan> AllCells(const cv::Size& cells) {
  std::vector<GridRowSpan> spans;
  spans.reserve(cells.height);
  for (int gy = 0; gy < cells.height; ++gy) spans.push_back({gy, 0, cells.width - 1});
  return spans;
}

GridSimilarity ComputeGridSimilarityInSpans(const TemplateLevel& level, const SceneLevel& scene,
                                            std::span<const GridRowSpan> spans,
                                            const SimilarityOptions& options) {
  return ComputeGridSimilarityInSpans(level, scene, SummarizeTemplateLevel(level, scene), spans,
                                      options);
}

GridSimilarity ComputeGridSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                     const TemplateLevelSummary& summary,
                                     const SimilarityOptions& options) {
  return ScoreGrid(level, scene, summary, AllCells(GridPositionCount(summary.extent, scene)),
                   options);
}

GridSimilarity ComputeGridSimilarityInSpans(const TemplateLevel& level, const SceneLevel& scene,
                                            const TemplateLevelSummary& summary,
                                            std::span<const GridRowSpan> spans,
                                            const SimilarityOptions& options) {
  return ScoreGrid(level, scene, summary, spans, options);
}

void ComputeSpanSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                           const TemplateLevelSummary& summary, std::span<const GridRowSpan> spans,
                           std::vector<std::uint16_t>& sums, const SimilarityOptions& options) {
  const cv::Size cells = GridPositionCount(summary.extent, scene);
  const GridRowSpan* previous = nullptr;
  for (const GridRowSpan& span : spans) {
    const bool inside = span.row >= 0 && span.row < cells.height && span.first_column >= 0 &&
                        span.first_column <= span.last_column && span.last_column < cells.width;
    const bool after_previous =
        previous == nullptr || span.row > previous->row ||
        (span.row == previous->row && span.first_column > previous->last_column);
    if (!inside || !after_previous) {
      throw Error("span similarity: spans must lie within the grid, sorted and apart (row " +
                  std::to_string(span.row) + ", columns " + std::to_string(span.first_column) +
                  ".." + std::to_string(span.last_column) + ")");
    }
    previous = &span;
  }
  ScoreCells(level, scene, summary, spans, options, sums);
}

LocalSimilarity ComputeLocalSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                       const cv::Rect& window_px,
                                       const SimilarityOptions& options) {
  return ComputeLocalSimilarity(level, scene, SummarizeTemplateLevel(level, scene), window_px,
                                options);
}

LocalSimilarity ComputeLocalSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                       const TemplateLevelSummary& summary,
                                       const cv::Rect& window_px,
                                       const SimilarityOptions& options) {
  LocalSimilarity result;
  result.window_px = window_px & ValidRect(summary.extent, scene.size_px);
  result.feature_count = summary.usable_features;
  if (result.window_px.empty()) {
    result.window_px = cv::Rect();
    return result;
  }
  if (result.feature_count == 0) {
    result.sums = cv::Mat::zeros(result.window_px.size(), CV_16UC1);
    return result;
  }
  result.sums.create(result.window_px.size(), CV_16UC1);  // every row is copied in below

  const cv::Rect& window = result.window_px;
  const std::size_t step = CommonResponseStep(level, scene);
  // Each window row gets its own block-rounded stretch of the buffer, so rounding never spills
  // into the next row.
  const int stride = RoundUpToSimdBlock(window.width);
  thread_local std::vector<Run> runs;
  runs.clear();
  for (int r = 0; r < window.height; ++r) {
    runs.push_back(Run{r * stride, static_cast<std::ptrdiff_t>(r * step), window.width});
  }
  thread_local std::vector<const std::uint8_t*> sources;
  sources.clear();
  ForEachUsableFeature(level, scene, [&](const Feature& f) {
    const cv::Mat& map = scene.responses[ModalityIndex(f.modality)][f.label];
    sources.push_back(map.ptr<std::uint8_t>(window.y + f.y) + window.x + f.x);
  });
  thread_local std::vector<std::uint16_t> flat;
  AccumulateRuns(sources, runs, window.height * stride, options, flat);
  for (int r = 0; r < window.height; ++r) {
    std::copy_n(flat.begin() + static_cast<std::ptrdiff_t>(r) * stride, window.width,
                result.sums.ptr<std::uint16_t>(r));
  }
  return result;
}

int ExactAlignmentScore(const TemplateLevel& level, const SceneLevel& scene,
                        const cv::Point& top_left_px) {
  return ExactAlignmentScores(level, scene, {top_left_px}).front();
}

std::vector<int> ExactAlignmentScores(const TemplateLevel& level, const SceneLevel& scene,
                                      const std::vector<cv::Point>& top_left_px) {
  return ExactAlignmentScores(level, scene, SummarizeTemplateLevel(level, scene), top_left_px);
}

std::vector<int> ExactAlignmentScores(const TemplateLevel& level, const SceneLevel& scene,
                                      const TemplateLevelSummary& summary,
                                      const std::vector<cv::Point>& top_left_px) {
  const cv::Rect valid = ValidRect(summary.extent, scene.size_px);
  for (const cv::Point& position : top_left_px) {
    if (!valid.contains(position)) {
      throw Error("exact alignment asked at (" + std::to_string(position.x) + ", " +
                  std::to_string(position.y) + "), where the template does not fit the scene");
    }
  }
  std::vector<int> scores(top_left_px.size(), 0);
  ForEachUsableFeature(level, scene, [&](const Feature& f) {
    const cv::Mat& quantized = scene.quantized[ModalityIndex(f.modality)];
    const std::uint8_t* similarity = BitmaskSimilarityRow(f.label);
    for (std::size_t i = 0; i < top_left_px.size(); ++i) {
      const cv::Point& p = top_left_px[i];
      scores[i] += similarity[quantized.at<std::uint8_t>(p.y + f.y, p.x + f.x)];
    }
  });
  return scores;
}

}  // namespace layermod
