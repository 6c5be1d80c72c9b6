// SPDX-License-Identifier: MIT
#include "match/matcher.h"

#include <tbb/blocked_range.h>
#include <tbb/collaborative_call_once.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "match/candidate_area.h"
#include "match/occluders.h"
#include "match/similarity.h"
#include "util/error.h"

namespace layermod {
namespace {

// A match before suppression, with what suppression needs.
struct Candidate {
  RawMatch match;
  std::int32_t obj_id = 0;
  cv::Point2f centre_px;
  // What matches are ordered by: the similarity with the hidden features (on occluders, past the
  // image) credited as where templates are ranked (Occluders::hidden_credit). A match mostly hidden
  // has shown little, and its visible features alone would put it ahead of matches in full
  // view; without hidden features it is match.similarity_percent.
  float rank_percent = 0.0f;
};

struct CoarseHit {
  int sum = 0;
  cv::Point cell;
  float percent = 0.0f;       // SimilarityPercent of sum
  float rise_percent = 0.0f;  // RisePercent: what hits are ranked by across templates
};

struct Refined {
  cv::Point position_px;
  int sum = 0;
};

// The highest level both the template and the scene have that can be scored together with every
// level below it, i.e. up to the first level without a feature of a modality the scene has
// (-1: none). Needs only one such feature per level.
// `facts`: TemplateFactsOf the template.
int UsableTopLevel(const TemplateFacts& facts, const PreparedScene& scene) {
  const int available = std::min(static_cast<int>(facts.size()), scene.LevelCount());
  int top = -1;
  for (int level = 0; level < available; ++level) {
    const SceneLevel& scene_level = scene.Level(level);
    const auto& counts = facts[static_cast<std::size_t>(level)].features_by_modality;
    bool usable = false;
    for (std::size_t m = 0; m < counts.size(); ++m) {
      usable = usable || (counts[m] > 0 && scene_level.present[m]);
    }
    if (!usable) break;
    top = level;
  }
  return top;
}

// The summary of one level against the scene's.
TemplateLevelSummary SummarizeLevel(const TemplateFacts& facts, int level,
                                    const PreparedScene& scene) {
  return SummarizeFacts(facts[static_cast<std::size_t>(level)], scene.Level(level));
}

// The summaries of levels 0..UsableTopLevel (empty when none can be scored).
std::vector<TemplateLevelSummary> UsableLevels(const TemplateFacts& facts,
                                               const PreparedScene& scene) {
  std::vector<TemplateLevelSummary> summaries;
  const int top = UsableTopLevel(facts, scene);
  for (int level = 0; level <= top; ++level) {
    summaries.push_back(SummarizeLevel(facts, level, scene));
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

// Level-0 pixels per grid cell of pyramid level `level` (spread T there, times 2^level).
int CellSpanPx(const SceneLevel& scene_level, int level) { return scene_level.spread_px << level; }

CandidateGeometry Geometry(const TemplateRecord& record, int top, const SceneLevel& level) {
  const cv::Point half_box(record.levels[0].width / 2, record.levels[0].height / 2);
  const bool has_anchor = record.centre_offset_px != cv::Point2f(0.0f, 0.0f);
  const cv::Point anchor = has_anchor
                               ? cv::Point(static_cast<int>(std::lround(record.centre_offset_px.x)),
                                           static_cast<int>(std::lround(record.centre_offset_px.y)))
                               : half_box;
  return {CellSpanPx(level, top), anchor, half_box};
}

// The hits, best first, at most `max_hits`.
void KeepBestHits(std::vector<CoarseHit>& hits, int max_hits) {
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
}

// The best cell at or above `min_sum` (the first in scan order among equals), as CoarseHits
// would give it, without collecting the others: `sums` as there.
std::vector<CoarseHit> BestHit(const std::vector<GridRowSpan>& spans,
                               const std::vector<std::uint16_t>& sums, int min_sum) {
  std::vector<CoarseHit> hits;
  const std::uint16_t* row = sums.data();
  int best_sum = min_sum - 1;
  for (const GridRowSpan& span : spans) {
    const int length = span.last_column - span.first_column + 1;
    const std::uint16_t* best = std::max_element(row, row + length);  // the first of equals
    if (*best > best_sum) {
      best_sum = *best;
      hits.assign(1, {best_sum, {span.first_column + static_cast<int>(best - row), span.row}});
    }
    row += length;
  }
  return hits;
}

// Cells at or above the threshold, best first, at most `max_hits`: `sums` holds the scores of the
// cells of `spans`, span after span (ComputeSpanSimilarity).
std::vector<CoarseHit> CoarseHits(const std::vector<GridRowSpan>& spans,
                                  const std::vector<std::uint16_t>& sums, int feature_count,
                                  float threshold_percent, int max_hits) {
  // The threshold is above 0, so a template without usable features has no hit.
  const int min_sum = std::max(MinimumSumForPercent(threshold_percent, feature_count), 1);
  if (max_hits == 1) return BestHit(spans, sums, min_sum);
  std::vector<CoarseHit> hits;
  const std::uint16_t* row = sums.data();
  for (const GridRowSpan& span : spans) {
    const int length = span.last_column - span.first_column + 1;
    // Most spans hold no hit: a (vectorized) maximum rejects them without a branch per cell.
    if (*std::max_element(row, row + length) >= min_sum) {
      for (int i = 0; i < length; ++i) {
        if (row[i] >= min_sum) hits.push_back({row[i], {span.first_column + i, span.row}});
      }
    }
    row += length;
  }
  KeepBestHits(hits, max_hits);
  return hits;
}

// The best position of the window: highest spread score; among equals, the best pixel-exact
// alignment; then the one nearest the window centre; then the first in scan order.
std::optional<Refined> RefineInWindow(const TemplateLevel& level, const SceneLevel& scene,
                                      const TemplateLevelSummary& summary,
                                      const cv::Rect& window_px,
                                      const SimilarityOptions& similarity) {
  const LocalSimilarity local =
      ComputeLocalSimilarity(level, scene, summary, window_px, similarity);
  if (local.window_px.empty() || local.feature_count == 0) return std::nullopt;
  // The positions of the highest sum, in scan order, found in one pass.
  Refined best;
  best.sum = -1;
  thread_local std::vector<cv::Point> ties;  // reused: one window after another
  ties.clear();
  for (int r = 0; r < local.sums.rows; ++r) {
    const auto* row = local.sums.ptr<std::uint16_t>(r);
    for (int c = 0; c < local.sums.cols; ++c) {
      if (row[c] < best.sum) continue;
      if (row[c] > best.sum) {
        best.sum = row[c];
        ties.clear();
      }
      ties.emplace_back(local.window_px.x + c, local.window_px.y + r);
    }
  }
  best.position_px = ties.front();
  if (ties.size() == 1) return best;  // nothing to break
  const cv::Point2d centre(window_px.x + (window_px.width - 1) / 2.0,
                           window_px.y + (window_px.height - 1) / 2.0);
  const std::vector<int> exact = ExactAlignmentScores(level, scene, summary, ties);
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

// Refines one coarse hit down the pyramid to level 0. `summaries`: UsableLevels of the record.
std::optional<Refined> RefineHit(const TemplateRecord& record,
                                 const std::vector<TemplateLevelSummary>& summaries,
                                 const PreparedScene& scene, int top, const CoarseHit& hit,
                                 const SimilarityOptions& options) {
  const int top_spread = scene.Level(top).spread_px;
  const cv::Rect cell(hit.cell * top_spread, cv::Size(top_spread, top_spread));
  std::optional<Refined> refined =
      RefineInWindow(record.levels[top], scene.Level(top), summaries[top], cell, options);
  for (int level = top - 1; level >= 0 && refined; --level) {
    const int spread = scene.Level(level).spread_px;
    const cv::Rect window(refined->position_px * 2 - cv::Point(spread, spread),
                          cv::Size(2 * spread + 2, 2 * spread + 2));
    refined =
        RefineInWindow(record.levels[level], scene.Level(level), summaries[level], window, options);
  }
  return refined;
}

// One template's top-level hits and what refining them needs.
struct TemplateHits {
  const TemplateRecord* record = nullptr;
  const TemplateFacts* facts = nullptr;  // TemplateFactsOf the record
  const Occluders* occluders = nullptr;  // TemplateSearch::occluders
  int top = 0;                           // top pyramid level scored
  cv::Point half_box;
  std::vector<CoarseHit> hits;  // best first
};

// A coarse hit ranked across templates: by its RisePercent (templates have different feature
// counts, so their sums do not compare).
struct RankedHit {
  float rise_percent = 0.0f;
  std::uint32_t template_id = 0;
  std::size_t source = 0;  // index into the TemplateHits list
  std::size_t hit = 0;     // index into its hits
};

// How far a top-level hit rises above the template's other scored cells: 100 (s - m) / (S - m),
// s the hit's sum, m the mean sum of the other cells (0 when there are none) and S the highest
// sum the template can reach. Hits are ranked across templates by it, not by their similarity:
// a template with few top-level features (a part small in the image spans two or three cells)
// reaches 80 % almost anywhere, and by similarity alone its hits crowded out those that stand out
// from their surroundings. `total`: the sum over all `cells` scored, the hit's included.
float RisePercent(int sum, std::int64_t total, std::size_t cells, int feature_count) {
  const double others =
      cells > 1 ? static_cast<double>(total - sum) / static_cast<double>(cells - 1) : 0.0;
  const double headroom = static_cast<double>(kMaxFeatureScore * feature_count) - others;
  return static_cast<float>(100.0 * (sum - others) / std::max(headroom, 1.0));
}

TemplateHits ScoreTopLevel(const TemplateRecord& record, const TemplateFacts& facts,
                           const PreparedScene& scene, const MatchOptions& options,
                           const CandidateArea& area) {
  TemplateHits result;
  result.record = &record;
  result.facts = &facts;
  if (record.status == TemplateStatus::kTooFewFeatures) return result;
  // Only the scored level is summarised here: the levels below it only for the templates whose
  // hits get refined (RefinedSummaries).
  const int top = UsableTopLevel(facts, scene);
  if (top < 0) return result;
  const SceneLevel& top_level = scene.LinearizedLevel(top);
  const TemplateLevelSummary top_summary = SummarizeLevel(facts, top, scene);
  const cv::Size cells = GridPositionCount(top_summary.extent, top_level);
  if (cells.empty()) return result;
  const SimilarityOptions similarity{Accumulator::kAuto, options.simd};
  const CandidateGeometry geometry = Geometry(record, top, top_level);
  thread_local std::vector<GridRowSpan> scored;  // reused: one template after another
  if (area.restricted) {
    NearCells(geometry.cell_span_px, geometry.anchor, cells, area, scored);
  } else {
    scored = AllCells(cells);
  }
  if (scored.empty()) return result;
  thread_local std::vector<std::uint16_t> sums;
  ComputeSpanSimilarity(record.levels[top], top_level, top_summary, scored, sums, similarity);
  result.top = top;
  result.half_box = geometry.half_box;
  result.hits = CoarseHits(scored, sums, top_summary.usable_features, options.threshold_percent,
                           options.max_candidates_per_template);
  if (result.hits.empty()) return result;  // most templates: no sum over the cells needed
  const std::int64_t total = std::accumulate(sums.begin(), sums.end(), std::int64_t{0});
  for (CoarseHit& hit : result.hits) {
    hit.percent = SimilarityPercent(hit.sum, top_summary.usable_features);
    hit.rise_percent = RisePercent(hit.sum, total, sums.size(), top_summary.usable_features);
  }
  return result;
}

// The hits refined: those that rise most above their template's other cells (RisePercent), over
// all templates, at most `budget`.
std::vector<RankedHit> RankHits(const std::vector<TemplateHits>& per_template, std::size_t budget) {
  std::vector<RankedHit> ranked;
  for (std::size_t t = 0; t < per_template.size(); ++t) {
    const TemplateHits& source = per_template[t];
    for (std::size_t h = 0; h < source.hits.size(); ++h) {
      ranked.push_back({source.hits[h].rise_percent, source.record->id, t, h});
    }
  }
  const auto better = [&](const RankedHit& a, const RankedHit& b) {
    const cv::Point& cell_a = per_template[a.source].hits[a.hit].cell;
    const cv::Point& cell_b = per_template[b.source].hits[b.hit].cell;
    return std::make_tuple(-a.rise_percent, a.template_id, cell_a.y, cell_a.x) <
           std::make_tuple(-b.rise_percent, b.template_id, cell_b.y, cell_b.x);
  };
  if (ranked.size() > budget) {
    std::nth_element(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(budget),
                     ranked.end(), better);
    ranked.resize(budget);
  }
  return ranked;
}

// UsableLevels of every template with a ranked hit, once per template (indexed like
// `per_template`; empty for the others).
std::vector<std::vector<TemplateLevelSummary>> RefinedSummaries(
    const std::vector<TemplateHits>& per_template, const std::vector<RankedHit>& ranked,
    const PreparedScene& scene) {
  std::vector<std::size_t> sources;
  sources.reserve(ranked.size());
  for (const RankedHit& hit : ranked) sources.push_back(hit.source);
  std::sort(sources.begin(), sources.end());
  sources.erase(std::unique(sources.begin(), sources.end()), sources.end());
  std::vector<std::vector<TemplateLevelSummary>> summaries(per_template.size());
  tbb::parallel_for(std::size_t{0}, sources.size(), [&](std::size_t i) {
    summaries[sources[i]] = UsableLevels(*per_template[sources[i]].facts, scene);
  });
  return summaries;
}

// `summaries`: UsableLevels of the hit's template. With occluders, the features on them are
// counted out of the level-0 score.
std::optional<Candidate> RefineRankedHit(const TemplateHits& source,
                                         const std::vector<TemplateLevelSummary>& summaries,
                                         const CoarseHit& hit, const PreparedScene& scene,
                                         const MatchOptions& options) {
  const SimilarityOptions similarity{Accumulator::kAuto, options.simd};
  const std::optional<Refined> refined =
      RefineHit(*source.record, summaries, scene, source.top, hit, similarity);
  if (!refined) return std::nullopt;
  VisibleScore score{summaries.front().usable_features, 0, refined->sum};
  const cv::Rect box(refined->position_px, summaries.front().extent);
  if (source.occluders != nullptr && (box & source.occluders->clear_px) != box) {
    score =
        ScoreVisibleFeatures(source.record->levels[0], scene.Level(0),
                             source.occluders->masks.front(), refined->position_px, refined->sum);
    if (score.Visible() < options.min_visible_share * static_cast<float>(score.features)) {
      return std::nullopt;
    }
  }
  if (score.sum < MinimumSumForPercent(options.threshold_percent, score.Visible())) {
    return std::nullopt;
  }
  Candidate candidate;
  const float visible_share =
      score.features > 0 ? static_cast<float>(score.Visible()) / static_cast<float>(score.features)
                         : 0.0f;
  candidate.match = {refined->position_px.x, refined->position_px.y,
                     SimilarityPercent(score.sum, score.Visible()), source.record->id,
                     visible_share};
  candidate.obj_id = source.record->obj_id;
  candidate.centre_px = cv::Point2f(refined->position_px + source.half_box);
  candidate.rank_percent =
      score.hidden == 0
          ? candidate.match.similarity_percent
          : SimilarityPercent(score.sum + source.occluders->hidden_credit * score.hidden,
                              score.features);
  return candidate;
}

bool BetterMatch(const Candidate& a, const Candidate& b) {
  return std::make_tuple(-a.rank_percent, a.match.template_id, a.match.y, a.match.x) <
         std::make_tuple(-b.rank_percent, b.match.template_id, b.match.y, b.match.x);
}

// Greedy non-maximum suppression: best first, a match is dropped when a kept match of the same
// template has its centre within the radius (one template reaches one place from several coarse
// hits), or matches_per_location kept matches of the same object do.
std::vector<RawMatch> SuppressDuplicates(std::vector<Candidate> candidates,
                                         const MatchOptions& options) {
  std::sort(candidates.begin(), candidates.end(), BetterMatch);
  const float radius_sq = static_cast<float>(options.nms_radius_px) * options.nms_radius_px;
  std::vector<const Candidate*> kept;
  for (const Candidate& candidate : candidates) {
    if (static_cast<int>(kept.size()) >= options.max_matches) break;
    int neighbours = 0;
    bool same_template_near = false;
    for (const Candidate* other : kept) {
      const cv::Point2f offset = candidate.centre_px - other->centre_px;
      if (other->obj_id != candidate.obj_id || offset.dot(offset) > radius_sq) continue;
      ++neighbours;
      same_template_near |= other->match.template_id == candidate.match.template_id;
    }
    if (!same_template_near && neighbours < options.matches_per_location) {
      kept.push_back(&candidate);
    }
  }
  std::vector<RawMatch> matches;
  matches.reserve(kept.size());
  for (const Candidate* candidate : kept) matches.push_back(candidate->match);
  return matches;
}

}  // namespace

std::string_view SearchModeName(TemplateSearchMode search) {
  switch (search) {
    case TemplateSearchMode::kTree:
      return "tree";
    case TemplateSearchMode::kFlat:
      return "flat";
  }
  return "?";
}

TemplateSearchMode ParseSearchMode(std::string_view text) {
  for (TemplateSearchMode search : {TemplateSearchMode::kTree, TemplateSearchMode::kFlat}) {
    if (text == SearchModeName(search)) return search;
  }
  throw Error("search: expected tree or flat, got '" + std::string(text) + "'");
}

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
  if (matches_per_location < 1) {
    throw Error("match matches_per_location must be >= 1, got " +
                std::to_string(matches_per_location));
  }
  if (max_refinements < 1) {
    throw Error("match max_refinements must be >= 1, got " + std::to_string(max_refinements));
  }
  if (tree_refinements < 1) {
    throw Error("match tree_refinements must be >= 1, got " + std::to_string(tree_refinements));
  }
  if (!(tree_descend > 0.0f && tree_descend <= 1.0f)) {
    throw Error("tree descend share must be in (0, 1], got " + std::to_string(tree_descend));
  }
  if (!(min_visible_share > 0.0f && min_visible_share <= 1.0f)) {
    throw Error("match min_visible_share must be in (0, 1], got " +
                std::to_string(min_visible_share));
  }
  if (max_candidates_per_template < 1) {
    throw Error("match max_candidates_per_template must be >= 1, got " +
                std::to_string(max_candidates_per_template));
  }
}

struct PreparedScene::LazyLevel {
  SceneLevel level;
  tbb::collaborative_once_flag linearized;
  // Set once the linear memories are built: every template scored asks, and the once-flag's
  // own check costs more than this load.
  std::atomic<bool> ready{false};
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

PreparedScene::PreparedScene(std::vector<SceneLevel> levels) {
  levels_.resize(levels.size());
  for (std::size_t level = 0; level < levels.size(); ++level) {
    levels_[level] = std::make_unique<LazyLevel>();
    levels_[level]->level = std::move(levels[level]);
    levels_[level]->ready.store(levels_[level]->level.linearized, std::memory_order_release);
  }
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
  if (lazy.ready.load(std::memory_order_acquire)) return lazy.level;
  tbb::collaborative_call_once(lazy.linearized, [&] {
    LinearizeSceneLevel(lazy.level);
    lazy.ready.store(true, std::memory_order_release);
  });
  return lazy.level;
}

TemplateFacts TemplateFactsOf(const TemplateRecord& record, std::span<const int> spread_px) {
  TemplateFacts facts;
  facts.reserve(record.levels.size());
  try {
    for (std::size_t level = 0; level < record.levels.size(); ++level) {
      const bool top = level + 1 == record.levels.size();
      const int spread = top && level < spread_px.size() ? spread_px[level] : 0;
      facts.push_back(LevelFacts(record.levels[level], spread));
    }
  } catch (const Error& error) {
    throw Error("template " + std::to_string(record.id) + ": " + error.what());
  }
  return facts;
}

std::vector<TemplateFacts> TemplateFactsOf(std::span<const TemplateRecord> templates,
                                           std::span<const int> spread_px) {
  std::vector<TemplateFacts> facts(templates.size());
  tbb::parallel_for(std::size_t{0}, templates.size(),
                    [&](std::size_t i) { facts[i] = TemplateFactsOf(templates[i], spread_px); });
  return facts;
}

std::vector<RawMatch> MatchTemplates(const PreparedScene& scene,
                                     std::span<const TemplateRecord> templates,
                                     const MatchOptions& options,
                                     const std::vector<cv::Point>* candidate_points,
                                     int candidate_radius_px) {
  const TemplateSearch search{templates, candidate_points, {}};
  return MatchTemplateGroups(scene, std::span<const TemplateSearch>(&search, 1), options,
                             candidate_radius_px);
}

namespace {

// `searches`, each with the facts of its templates: those that come without get them worked
// out here, into `worked_out`, so that scoring always reads facts.
std::vector<TemplateSearch> WithFacts(std::span<const TemplateSearch> searches,
                                      std::deque<std::vector<TemplateFacts>>& worked_out) {
  std::vector<TemplateSearch> complete(searches.begin(), searches.end());
  for (TemplateSearch& search : complete) {
    if (search.facts.empty()) {
      search.facts = worked_out.emplace_back(TemplateFactsOf(search.templates));
    } else if (search.facts.size() != search.templates.size()) {
      throw Error("template search: " + std::to_string(search.facts.size()) + " facts for " +
                  std::to_string(search.templates.size()) + " templates");
    }
  }
  return complete;
}

// Each cluster's best top-level similarity of its representative, with the threshold lowered
// by kRepresentativeMarginPercent; -1 where it has no hit even so.
std::vector<float> RepresentativeScores(const TemplateSearch& search, const CandidateArea& area,
                                        const PreparedScene& scene, const MatchOptions& options) {
  MatchOptions coarse = options;
  coarse.threshold_percent =
      std::max(1.0f, options.threshold_percent - kRepresentativeMarginPercent);
  coarse.max_candidates_per_template = 1;  // the best position is all the ranking needs
  std::vector<float> best(search.clusters.size(), -1.0f);
  tbb::parallel_for(std::size_t{0}, search.clusters.size(), [&](std::size_t c) {
    const std::uint32_t representative = search.clusters[c].representative;
    const TemplateHits hits = ScoreTopLevel(search.templates[representative],
                                            search.facts[representative], scene, coarse, area);
    if (!hits.hits.empty()) best[c] = hits.hits.front().percent;
  });
  return best;
}

// Whether `search` goes through its view tree: it has clusters, and the options neither ask
// for the flat search nor descend into every cluster.
bool SearchesTree(const TemplateSearch& search, const MatchOptions& options) {
  return !search.clusters.empty() && options.search == TemplateSearchMode::kTree &&
         options.tree_descend < 1.0f;
}

// The templates of `search` to score, as indices into search.templates: all of them, or with
// view clusters the members of the clusters whose representatives score best (see
// TemplateSearch).
std::vector<std::size_t> TemplatesToScore(const TemplateSearch& search, const CandidateArea& area,
                                          const PreparedScene& scene, const MatchOptions& options) {
  std::vector<std::size_t> chosen;
  if (!SearchesTree(search, options)) {
    chosen.resize(search.templates.size());
    std::iota(chosen.begin(), chosen.end(), std::size_t{0});
    return chosen;
  }
  const std::vector<float> best = RepresentativeScores(search, area, scene, options);
  std::vector<std::size_t> order(best.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return best[a] > best[b]; });
  const auto descended = std::min(
      order.size(),
      static_cast<std::size_t>(std::ceil(options.tree_descend * static_cast<float>(best.size()))));
  for (std::size_t k = 0; k < descended && best[order[k]] >= 0.0f; ++k) {
    for (std::uint32_t member : search.clusters[order[k]].members) chosen.push_back(member);
  }
  return chosen;
}

}  // namespace

std::vector<RawMatch> MatchTemplateGroups(const PreparedScene& scene,
                                          std::span<const TemplateSearch> searches,
                                          const MatchOptions& options, int candidate_radius_px) {
  options.Validate();
  if (candidate_radius_px < 0) {
    throw Error("candidate radius must be >= 0 px, got " + std::to_string(candidate_radius_px));
  }
  ResolveSimdPath(options.simd);  // an unsupported forced path fails here, not in a worker
  if (scene.LevelCount() == 0) return {};
  // Any radius beyond the image diagonal reaches everything; clamping keeps the arithmetic small.
  const int radius_px = std::min(candidate_radius_px, 1 << 20);
  // A template to score: where (its search's candidate area) and on which scene (with
  // occluders, the one templates are ranked on).
  struct Work {
    const TemplateRecord* record = nullptr;
    const TemplateFacts* facts = nullptr;
    const CandidateArea* area = nullptr;
    const PreparedScene* ranked = nullptr;
    const Occluders* occluders = nullptr;
  };
  std::deque<std::vector<TemplateFacts>> worked_out;
  const std::vector<TemplateSearch> complete = WithFacts(searches, worked_out);
  std::vector<CandidateArea> areas;
  std::vector<int> spans;  // the top-level cell spans templates can have on this scene
  spans.reserve(static_cast<std::size_t>(scene.LevelCount()));
  for (int level = 0; level < scene.LevelCount(); ++level) {
    spans.push_back(CellSpanPx(scene.Level(level), level));
  }
  std::vector<Work> work;
  bool through_tree = false;
  areas.reserve(complete.size());
  for (const TemplateSearch& search : complete) {
    through_tree = through_tree || SearchesTree(search, options);
    const PreparedScene& ranked = search.occluders == nullptr ? scene : *search.occluders->ranked;
    areas.push_back(search.candidate_points == nullptr
                        ? CandidateArea{}
                        : MakeCandidateArea(*search.candidate_points, radius_px,
                                            scene.Level(0).size_px, spans));
    for (const std::size_t index : TemplatesToScore(search, areas.back(), ranked, options)) {
      work.push_back({&search.templates[index], &search.facts[index], &areas.back(), &ranked,
                      search.occluders});
    }
  }
  // Two passes: every template scores its top level; then only the best hits over all
  // templates are refined down the pyramid (refinement costs far more per hit than scoring).
  std::vector<TemplateHits> per_template(work.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, work.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        per_template[i] = ScoreTopLevel(*work[i].record, *work[i].facts,
                                                        *work[i].ranked, options, *work[i].area);
                        per_template[i].occluders = work[i].occluders;
                      }
                    });
  const std::vector<RankedHit> ranked = RankHits(
      per_template,
      static_cast<std::size_t>(through_tree ? options.tree_refinements : options.max_refinements));
  const std::vector<std::vector<TemplateLevelSummary>> summaries =
      RefinedSummaries(per_template, ranked, scene);
  std::vector<std::optional<Candidate>> refined(ranked.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ranked.size()),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i) {
                        const TemplateHits& source = per_template[ranked[i].source];
                        refined[i] = RefineRankedHit(source, summaries[ranked[i].source],
                                                     source.hits[ranked[i].hit], scene, options);
                      }
                    });
  std::vector<Candidate> candidates;
  for (const std::optional<Candidate>& candidate : refined) {
    if (candidate) candidates.push_back(*candidate);
  }
  return SuppressDuplicates(std::move(candidates), options);
}

}  // namespace layermod
