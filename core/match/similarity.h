// SPDX-License-Identifier: MIT
// Stage 4 of LineMOD matching (PAMI 2012, §2.5-2.6): the similarity of one template level with a
// scene level, accumulated from the precomputed responses with saturating SIMD additions.
//
// Score of a template at top-left position p: the sum over its features f of the response of
// f's orientation at p + (f.x, f.y) (kMaxFeatureScore per perfectly matching feature). Features
// whose modality the scene lacks are left out, of the score and of the feature count. Only
// positions where the template's extent fits inside the scene are evaluated, so no feature ever
// falls outside it; the spreading (spread.h) still lets a template touching the border be found.
#pragma once

#include <array>

#include <cstdint>
#include <opencv2/core.hpp>
#include <span>
#include <vector>

#include "features/feature.h"
#include "match/scene_level.h"
#include "match/simd.h"

namespace layermod {

// Up to 63 features the sums fit in a byte (63 * 4 = 252): one 8-bit accumulator. Beyond, the
// 16-bit path accumulates chunks of 63 features in 8 bits (they cannot saturate) and widens each
// chunk into 16-bit totals.
inline constexpr int kMax8BitFeatures = 63;
// The most features a template level may have: their total score must fit in 16 bits.
inline constexpr int kMaxTemplateFeatures = 65535 / kMaxFeatureScore;

enum class Accumulator { kAuto, k8Bit, k16Bit };

struct SimilarityOptions {
  Accumulator accumulator = Accumulator::kAuto;  // k8Bit with more than 63 features throws
  SimdPath simd = SimdPath::kAuto;
};

// Throws Error unless every feature has x, y >= 0, a label 0..7 and a known modality, and the
// level has at most kMaxTemplateFeatures features.
void CheckTemplateLevel(const TemplateLevel& level);

// A feature as grid scoring reads it on scene levels of one spread T: its linear memory
// (SceneLevel::memory_rows at `memory_row`, MemoryRowKey of its modality, label and position
// modulo T) and its cell offset (x / T, y / T).
struct GridFeature {
  std::uint16_t memory_row = 0;
  std::uint8_t cell_x = 0;
  std::uint8_t cell_y = 0;
};

// What scoring a template level against a scene level needs to know, from one pass over its
// features (which also checks them, as CheckTemplateLevel).
struct TemplateLevelSummary {
  int usable_features = 0;  // UsableFeatureCount
  cv::Size extent;          // TemplateExtent
  // The level's features in order, as GridFeatures for this scene's spread, or empty: grid
  // scoring then works them out from the features (the same sums either way).
  std::span<const GridFeature> grid_features;
};
TemplateLevelSummary SummarizeTemplateLevel(const TemplateLevel& level, const SceneLevel& scene);

// What no frame changes in a level's summary: its extent and its features per modality. A
// detector works these out once per template (LevelFacts checks the features as
// CheckTemplateLevel does), so that a frame does not walk every scored template's features.
struct TemplateLevelFacts {
  cv::Size extent;                                         // TemplateExtent
  std::array<int, kModalityCount> features_by_modality{};  // index ModalityIndex
  // With grid_spread_px > 0: every feature as a GridFeature for scene levels of that spread (the
  // level a detector scores on the grid), so that scoring reads no feature coordinates.
  int grid_spread_px = 0;
  std::vector<GridFeature> grid_features;
};
// `grid_spread_px` > 0 adds the grid features for that spread (1..kMaxSpreadPx), unless a
// feature lies too far out for GridFeature's cell offsets (more than 255 cells): then none.
TemplateLevelFacts LevelFacts(const TemplateLevel& level, int grid_spread_px = 0);
// The summary against `scene`, from the facts: equal to SummarizeTemplateLevel's, with the grid
// features when they are for the scene's spread.
TemplateLevelSummary SummarizeFacts(const TemplateLevelFacts& facts, const SceneLevel& scene);

// The template's extent from its top-left: its box, grown to hold every feature.
cv::Size TemplateExtent(const TemplateLevel& level);
// Top-left positions where the extent fits in a scene of `scene_size_px` (empty if none).
cv::Rect ValidPositions(const TemplateLevel& level, const cv::Size& scene_size_px);
// Features whose modality `scene` has: the denominator of the similarity percentage.
int UsableFeatureCount(const TemplateLevel& level, const SceneLevel& scene);
// 100 * sum / (kMaxFeatureScore * feature_count); 0 without features.
float SimilarityPercent(int sum, int feature_count);
// The smallest sum whose SimilarityPercent reaches `percent` (exactly consistent with it), so
// that thresholds compare integers; kMaxFeatureScore * feature_count + 1 when none does.
int MinimumSumForPercent(float percent, int feature_count);

// Scores at the grid positions (gx * T, gy * T) that are valid positions.
struct GridSimilarity {
  int spread_px = 0;
  int feature_count = 0;  // usable features
  cv::Mat sums;           // CV_16UC1, GridPositionCount rows x cols; 0 where not requested
};

// Number of valid grid positions (columns, rows): (gx, gy) with (gx * T, gy * T) valid.
cv::Size GridPositionCount(const TemplateLevel& level, const SceneLevel& scene);
cv::Size GridPositionCount(const cv::Size& template_extent, const SceneLevel& scene);

// Scores every valid grid position, or only those where `cell_mask` (CV_8UC1 of
// GridPositionCount size) is non-zero. Throws Error for a mask of another size or type.
GridSimilarity ComputeGridSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                     const cv::Mat& cell_mask = cv::Mat(),
                                     const SimilarityOptions& options = {});

// Grid cells (row, first_column..last_column inclusive) to score.
struct GridRowSpan {
  int row = 0;
  int first_column = 0;
  int last_column = 0;
};

// Every cell of a grid of `cells` (GridPositionCount), one span per row.
std::vector<GridRowSpan> AllCells(const cv::Size& cells);

// Scores only the cells of `spans` (any order, may overlap; clipped to GridPositionCount); the
// other cells hold 0. Cheaper than a mask when few cells are wanted: no pass over the whole grid.
GridSimilarity ComputeGridSimilarityInSpans(const TemplateLevel& level, const SceneLevel& scene,
                                            std::span<const GridRowSpan> spans,
                                            const SimilarityOptions& options = {});
// Both with the level's SummarizeTemplateLevel against this scene level already at hand (the
// matcher has it from choosing the template's levels): every valid cell, or the spans' cells.
GridSimilarity ComputeGridSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                     const TemplateLevelSummary& summary,
                                     const SimilarityOptions& options = {});
GridSimilarity ComputeGridSimilarityInSpans(const TemplateLevel& level, const SceneLevel& scene,
                                            const TemplateLevelSummary& summary,
                                            std::span<const GridRowSpan> spans,
                                            const SimilarityOptions& options = {});

// The sums at the cells of `spans`, one per cell, span after span: ComputeGridSimilarityInSpans
// without the grid-sized image, for callers that read the scored cells only (the matcher scores
// tens of thousands of templates per frame, each at a few dozen cells). `spans` must lie within
// GridPositionCount, sorted by row, then column, and must not overlap; throws Error otherwise.
// `sums` is reused (cleared, then filled).
void ComputeSpanSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                           const TemplateLevelSummary& summary, std::span<const GridRowSpan> spans,
                           std::vector<std::uint16_t>& sums, const SimilarityOptions& options = {});

// Scores at every pixel position of a small window (coarse-to-fine refinement).
struct LocalSimilarity {
  cv::Rect window_px;     // evaluated top-left positions: the requested window, clipped to valid
  int feature_count = 0;  // usable features
  cv::Mat sums;  // CV_16UC1 of window_px.size(); sums(r, c) scores (window_px.x + c, .y + r)
};

LocalSimilarity ComputeLocalSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                       const cv::Rect& window_px,
                                       const SimilarityOptions& options = {});
// The same with the level's SummarizeTemplateLevel against this scene level already at hand:
// refinement scores one template in many windows and need not re-read its features each time.
LocalSimilarity ComputeLocalSimilarity(const TemplateLevel& level, const SceneLevel& scene,
                                       const TemplateLevelSummary& summary,
                                       const cv::Rect& window_px,
                                       const SimilarityOptions& options = {});

// Score of the template at `top_left_px` against the UNSPREAD quantized scene: how well its
// features align pixel-exactly. Within a plateau of equal spread scores (a true placement scores
// fully over T x T positions), this tells where the template actually sits. Throws Error for a
// position outside ValidPositions.
int ExactAlignmentScore(const TemplateLevel& level, const SceneLevel& scene,
                        const cv::Point& top_left_px);
// The same at several positions (the template is checked once).
std::vector<int> ExactAlignmentScores(const TemplateLevel& level, const SceneLevel& scene,
                                      const std::vector<cv::Point>& top_left_px);
// The same with the level's summary at hand (see ComputeLocalSimilarity).
std::vector<int> ExactAlignmentScores(const TemplateLevel& level, const SceneLevel& scene,
                                      const TemplateLevelSummary& summary,
                                      const std::vector<cv::Point>& top_left_px);

}  // namespace layermod
