// SPDX-License-Identifier: MIT
#include "match/matcher.h"

#include <tbb/blocked_range.h>
#include <tbb/collaborative_call_once.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>

#include "match/similarity.h"
#include "util/error.h"

namespace layermod {
namespace {

// A match before suppression, with what suppression needs.
struct Candidate {
  RawMatch match;
  std::int32_t obj_id = 0;
  cv::Point2f centre_px;
};

struct CoarseHit {
  int sum = 0;
  cv::Point cell;
};

struct Refined {
  cv::Point position_px;
  int sum = 0;
};

// Where the candidate points restrict the search, and how far.
struct CandidateArea {
  const std::vector<cv::Point>* points = nullptr;
  int radius_px = 0;
};

int FloorDiv(int value, int divisor) {
  return value >= 0 ? value / divisor : -((-value + divisor - 1) / divisor);
}

// The summary of each level both the template and the scene have, up to the first one without
// a feature of a modality the scene has (such a level cannot be scored). Throws Error naming the
// template for invalid features.
std::vector<TemplateLevelSummary> UsableLevels(const TemplateRecord& record,
                                               const PreparedScene& scene) {
  const int available = std::min(static_cast<int>(record.levels.size()), scene.LevelCount());
  std::vector<TemplateLevelSummary> summaries;
  try {
    for (int level = 0; level < available; ++level) {
      const TemplateLevelSummary summary =
          SummarizeTemplateLevel(record.levels[level], scene.Level(level));
      if (summary.usable_features == 0) break;
      summaries.push_back(summary);
    }
  } catch (const Error& error) {
    throw Error("template " + std::to_string(record.id) + ": " + error.what());
  }
  return summaries;
}

// Grid cell (gx, gy) of level `top` stands for the level-0 top-left positions
// [gx * T * 2^top, (gx + 1) * T * 2^top) (spread.h), i.e. for template anchors shifted by the
// anchor offset.
struct CandidateGeometry {
  int cell_span_px = 0;  // level-0 pixels per top-level cell
  cv::Point anchor;      // level-0 box top-left -> the template's anchor (see matcher.h)
  cv::Point half_box;    // level-0 box top-left -> box centre (for duplicate suppression)
};

CandidateGeometry Geometry(const TemplateRecord& record, int top, const SceneLevel& level) {
  const cv::Point half_box(record.levels[0].width / 2, record.levels[0].height / 2);
  const bool has_anchor = record.centre_offset_px != cv::Point2f(0.0f, 0.0f);
  const cv::Point anchor = has_anchor ? cv::Point(static_cast<int>(std::lround(record.centre_offset_px.x)),
                                                  static_cast<int>(std::lround(record.centre_offset_px.y)))
                                      : half_box;
  return {level.spread_px << top, anchor, half_box};
}

// Whether the anchors of cell (gx, gy) come within the radius of `point`.
bool CellNearPoint(int gx, int gy, const cv::Point& point, const CandidateGeometry& geometry,
                   int radius_px) {
  const int span = geometry.cell_span_px;
  const cv::Point top_left = point - geometry.anchor;  // puts the anchor on the point
  const int dx = std::max({gx * span - top_left.x, top_left.x - (gx * span + span - 1), 0});
  const int dy = std::max({gy * span - top_left.y, top_left.y - (gy * span + span - 1), 0});
  return static_cast<double>(dx) * dx + static_cast<double>(dy) * dy <=
         static_cast<double>(radius_px) * radius_px;
}

// The top-level cells near some candidate point, as a mask and as merged row spans: scored
// without a pass over the whole grid, and without scoring a cell twice where the neighbourhoods
// of neighbouring points overlap.
struct CandidateCells {
  cv::Size cells;
  std::vector<std::uint8_t> near;  // row-major over `cells`
  std::vector<GridRowSpan> spans;

  bool Contains(const cv::Point& cell) const {
    return near[static_cast<std::size_t>(cell.y) * cells.width + cell.x] != 0;
  }
};

CandidateCells NearCells(const CandidateGeometry& geometry, const cv::Size& cells,
                         const CandidateArea& area) {
  CandidateCells result{cells, std::vector<std::uint8_t>(static_cast<std::size_t>(cells.area()), 0),
                        {}};
  const int span = geometry.cell_span_px;
  for (const cv::Point& point : *area.points) {
    const cv::Point top_left = point - geometry.anchor;
    const int gx0 = std::max(FloorDiv(top_left.x - area.radius_px, span), 0);
    const int gx1 = std::min(FloorDiv(top_left.x + area.radius_px, span), cells.width - 1);
    const int gy0 = std::max(FloorDiv(top_left.y - area.radius_px, span), 0);
    const int gy1 = std::min(FloorDiv(top_left.y + area.radius_px, span), cells.height - 1);
    for (int gy = gy0; gy <= gy1; ++gy) {
      std::uint8_t* row = result.near.data() + static_cast<std::size_t>(gy) * cells.width;
      for (int gx = gx0; gx <= gx1; ++gx) {
        if (row[gx] == 0 && CellNearPoint(gx, gy, point, geometry, area.radius_px)) row[gx] = 1;
      }
    }
  }
  for (int gy = 0; gy < cells.height; ++gy) {
    const std::uint8_t* row = result.near.data() + static_cast<std::size_t>(gy) * cells.width;
    for (int gx = 0; gx < cells.width; ++gx) {
      if (row[gx] == 0) continue;
      const int first = gx;
      while (gx + 1 < cells.width && row[gx + 1] != 0) ++gx;
      result.spans.push_back({gy, first, gx});
    }
  }
  return result;
}

// Grid positions at or above the threshold that `accept` takes, best first, at most `max_hits`.
template <typename Accept>
std::vector<CoarseHit> CoarseHits(const GridSimilarity& grid, float threshold_percent, int max_hits,
                                  Accept&& accept) {
  // Cells not scored hold 0, which never passes: the threshold is above 0.
  const int min_sum = std::max(MinimumSumForPercent(threshold_percent, grid.feature_count), 1);
  std::vector<CoarseHit> hits;
  for (int gy = 0; gy < grid.sums.rows; ++gy) {
    const auto* row = grid.sums.ptr<std::uint16_t>(gy);
    // Most rows hold no hit: a (vectorized) maximum rejects them without a branch per cell.
    if (*std::max_element(row, row + grid.sums.cols) < min_sum) continue;
    for (int gx = 0; gx < grid.sums.cols; ++gx) {
      if (row[gx] >= min_sum && accept(cv::Point(gx, gy))) hits.push_back({row[gx], {gx, gy}});
    }
  }
  const auto better = [](const CoarseHit& a, const CoarseHit& b) {
    return std::make_tuple(-a.sum, a.cell.y, a.cell.x) <
           std::make_tuple(-b.sum, b.cell.y, b.cell.x);
  };
  if (static_cast<int>(hits.size()) > max_hits) {
    std::partial_sort(hits.begin(), hits.begin() + max_hits, hits.end(), better);
    hits.resize(max_hits);
  } else {
    std::sort(hits.begin(), hits.end(), better);
  }
  return hits;
}

// The best position of the window: highest spread score; among equals, the best pixel-exact
// alignment; then the one nearest the window centre; then the first in scan order.
std::optional<Refined> RefineInWindow(const TemplateLevel& level, const SceneLevel& scene,
                                      const cv::Rect& window_px,
                                      const SimilarityOptions& similarity) {
  const LocalSimilarity local = ComputeLocalSimilarity(level, scene, window_px, similarity);
  if (local.window_px.empty() || local.feature_count == 0) return std::nullopt;
  double max_sum = 0;
  cv::minMaxLoc(local.sums, nullptr, &max_sum);
  const cv::Point2d centre(window_px.x + (window_px.width - 1) / 2.0,
                           window_px.y + (window_px.height - 1) / 2.0);
  Refined best;
  best.sum = static_cast<int>(max_sum);
  std::vector<cv::Point> ties;
  for (int r = 0; r < local.sums.rows; ++r) {
    const auto* row = local.sums.ptr<std::uint16_t>(r);
    for (int c = 0; c < local.sums.cols; ++c) {
      if (row[c] == best.sum) ties.emplace_back(local.window_px.x + c, local.window_px.y + r);
    }
  }
  const std::vector<int> exact = ExactAlignmentScores(level, scene, ties);
  std::optional<std::tuple<int, double>> best_key;  // (-exact score, squared distance to centre)
  for (std::size_t i = 0; i < ties.size(); ++i) {
    const cv::Point2d offset = cv::Point2d(ties[i]) - centre;
    const std::tuple<int, double> key(-exact[i], offset.dot(offset));
    if (!best_key || key < *best_key) {  // strict: the first in scan order wins full ties
      best_key = key;
      best.position_px = ties[i];
    }
  }
  return best;
}

// Refines one coarse hit down the pyramid to level 0.
std::optional<Refined> RefineHit(const TemplateRecord& record, const PreparedScene& scene, int top,
                                 const CoarseHit& hit, const SimilarityOptions& options) {
  const int top_spread = scene.Level(top).spread_px;
  const cv::Rect cell(hit.cell * top_spread, cv::Size(top_spread, top_spread));
  std::optional<Refined> refined =
      RefineInWindow(record.levels[top], scene.Level(top), cell, options);
  for (int level = top - 1; level >= 0 && refined; --level) {
    const int spread = scene.Level(level).spread_px;
    const cv::Rect window(refined->position_px * 2 - cv::Point(spread, spread),
                          cv::Size(2 * spread + 2, 2 * spread + 2));
    refined = RefineInWindow(record.levels[level], scene.Level(level), window, options);
  }
  return refined;
}

std::vector<Candidate> MatchOne(const TemplateRecord& record, const PreparedScene& scene,
                                const MatchOptions& options, const CandidateArea& area) {
  if (record.status == TemplateStatus::kTooFewFeatures) return {};
  const std::vector<TemplateLevelSummary> levels = UsableLevels(record, scene);
  if (levels.empty()) return {};
  const int top = static_cast<int>(levels.size()) - 1;
  const SceneLevel& top_level = scene.LinearizedLevel(top);
  const cv::Size cells = GridPositionCount(levels[top].extent, top_level);
  if (cells.empty()) return {};
  const SimilarityOptions similarity{Accumulator::kAuto, options.simd};
  const CandidateGeometry geometry = Geometry(record, top, top_level);
  GridSimilarity grid;
  CandidateCells near;
  if (area.points == nullptr) {
    grid = ComputeGridSimilarity(record.levels[top], top_level, cv::Mat(), similarity);
  } else {
    near = NearCells(geometry, cells, area);
    if (near.spans.empty()) return {};
    grid = ComputeGridSimilarityInSpans(record.levels[top], top_level, near.spans, similarity);
  }
  const auto accept = [&](const cv::Point& cell) {
    return area.points == nullptr || near.Contains(cell);
  };
  const int min_level0_sum =
      MinimumSumForPercent(options.threshold_percent, levels[0].usable_features);
  std::vector<Candidate> candidates;
  for (const CoarseHit& hit :
       CoarseHits(grid, options.threshold_percent, options.max_candidates_per_template, accept)) {
    const std::optional<Refined> refined = RefineHit(record, scene, top, hit, similarity);
    if (!refined || refined->sum < min_level0_sum) continue;
    Candidate candidate;
    candidate.match = {refined->position_px.x, refined->position_px.y,
                       SimilarityPercent(refined->sum, levels[0].usable_features), record.id};
    candidate.obj_id = record.obj_id;
    candidate.centre_px = cv::Point2f(refined->position_px + geometry.half_box);
    candidates.push_back(candidate);
  }
  return candidates;
}

bool BetterMatch(const Candidate& a, const Candidate& b) {
  return std::make_tuple(-a.match.similarity_percent, a.match.template_id, a.match.y, a.match.x) <
         std::make_tuple(-b.match.similarity_percent, b.match.template_id, b.match.y, b.match.x);
}

// Greedy non-maximum suppression: best first, a match is dropped when a kept match of the same
// object has its centre within the radius.
std::vector<RawMatch> SuppressDuplicates(std::vector<Candidate> candidates,
                                         const MatchOptions& options) {
  std::sort(candidates.begin(), candidates.end(), BetterMatch);
  const float radius_sq = static_cast<float>(options.nms_radius_px) * options.nms_radius_px;
  std::vector<const Candidate*> kept;
  for (const Candidate& candidate : candidates) {
    if (static_cast<int>(kept.size()) >= options.max_matches) break;
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const Candidate* other) {
      const cv::Point2f offset = candidate.centre_px - other->centre_px;
      return other->obj_id == candidate.obj_id && offset.dot(offset) <= radius_sq;
    });
    if (!duplicate) kept.push_back(&candidate);
  }
  std::vector<RawMatch> matches;
  matches.reserve(kept.size());
  for (const Candidate* candidate : kept) matches.push_back(candidate->match);
  return matches;
}

}  // namespace

void MatchOptions::Validate() const {
  if (!(threshold_percent > 0.0f && threshold_percent <= 100.0f)) {
    throw Error("match threshold_percent must be in (0, 100], got " +
                std::to_string(threshold_percent));
  }
  if (nms_radius_px < 0) {
    throw Error("match nms_radius_px must be >= 0, got " + std::to_string(nms_radius_px));
  }
  if (max_matches < 1) {
    throw Error("match max_matches must be >= 1, got " + std::to_string(max_matches));
  }
  if (max_candidates_per_template < 1) {
    throw Error("match max_candidates_per_template must be >= 1, got " +
                std::to_string(max_candidates_per_template));
  }
}

struct PreparedScene::LazyLevel {
  SceneLevel level;
  tbb::collaborative_once_flag linearized;
};

PreparedScene::PreparedScene() = default;
PreparedScene::~PreparedScene() = default;
PreparedScene::PreparedScene(PreparedScene&&) noexcept = default;
PreparedScene& PreparedScene::operator=(PreparedScene&&) noexcept = default;

PreparedScene::PreparedScene(const std::vector<std::array<cv::Mat, kModalityCount>>& quantized,
                             const std::vector<int>& spread_px, SimdPath simd) {
  if (spread_px.size() < quantized.size()) {
    throw Error("the scene has " + std::to_string(quantized.size()) +
                " pyramid levels but spread T is given for " + std::to_string(spread_px.size()));
  }
  levels_.resize(quantized.size());
  tbb::parallel_for(std::size_t{0}, quantized.size(), [&](std::size_t level) {
    levels_[level] = std::make_unique<LazyLevel>();
    levels_[level]->level = BuildSceneResponses(quantized[level], spread_px[level], simd);
  });
}

const SceneLevel& PreparedScene::Level(int level) const {
  if (level < 0 || level >= LevelCount()) {
    throw Error("scene pyramid level " + std::to_string(level) + " does not exist (the scene has " +
                std::to_string(LevelCount()) + ")");
  }
  return levels_[level]->level;
}

const SceneLevel& PreparedScene::LinearizedLevel(int level) const {
  Level(level);  // range check
  LazyLevel& lazy = *levels_[level];
  tbb::collaborative_call_once(lazy.linearized, [&] { LinearizeSceneLevel(lazy.level); });
  return lazy.level;
}

std::vector<RawMatch> MatchTemplates(const PreparedScene& scene,
                                     std::span<const TemplateRecord> templates,
                                     const MatchOptions& options,
                                     const std::vector<cv::Point>* candidate_points,
                                     int candidate_radius_px) {
  options.Validate();
  if (candidate_radius_px < 0) {
    throw Error("candidate radius must be >= 0 px, got " + std::to_string(candidate_radius_px));
  }
  ResolveSimdPath(options.simd);  // an unsupported forced path fails here, not in a worker
  if (scene.LevelCount() == 0 || templates.empty()) return {};
  // Any radius beyond the image diagonal reaches everything; clamping keeps the arithmetic small.
  const CandidateArea area{candidate_points, std::min(candidate_radius_px, 1 << 20)};
  std::vector<std::vector<Candidate>> per_template(templates.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, templates.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        per_template[i] = MatchOne(templates[i], scene, options, area);
                      }
                    });
  std::vector<Candidate> candidates;
  for (auto& found : per_template) {
    candidates.insert(candidates.end(), found.begin(), found.end());
  }
  return SuppressDuplicates(std::move(candidates), options);
}

}  // namespace layermod
