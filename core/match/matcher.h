// SPDX-License-Identifier: MIT
// Stage 5 of LineMOD matching (PAMI 2012, §2.6-3): templates against a prepared scene, coarse to
// fine over the pyramid, optionally only around given candidate points (the Scene-Patch
// invocation, paper §3.4), then non-maximum suppression.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <span>
#include <string_view>
#include <vector>

#include "match/scene_level.h"
#include "match/simd.h"
#include "match/similarity.h"
#include "templates/template_record.h"
#include "templates/view_clusters.h"

namespace layermod {

// How a template set with view clusters (TemplateSearch::clusters) is searched.
enum class TemplateSearchMode {
  kTree,  // cluster representatives first, then the members of the best clusters
  kFlat,  // every template, as without clusters (for comparison)
};
std::string_view SearchModeName(TemplateSearchMode search);
TemplateSearchMode ParseSearchMode(std::string_view text);  // throws Error

struct MatchOptions {
  // Similarity a match needs, at the top level and at level 0. 70 rather than OpenCV's usual 80:
  // partly occluded parts score 70-80, and pose verification rejects the extra false matches.
  float threshold_percent = 70.0f;
  // Matches of one object (TemplateRecord::obj_id) whose box centres lie at most this far apart
  // (level-0 px) are duplicates: only the best is kept. Different objects never suppress each
  // other. 0 removes exact duplicates only.
  int nms_radius_px = 16;
  // Matches kept per neighbourhood of that radius: the best few templates at one place differ
  // in rotation, and the pose stage picks the one the depth confirms.
  int matches_per_location = 3;
  int max_matches = 100;  // best matches returned after suppression
  // Top-level positions refined per template, best first: bounds the work on cluttered scenes
  // where thousands of coarse positions pass the threshold.
  int max_candidates_per_template = 64;
  // Top-level hits refined down the pyramid per call (over all template sets of
  // MatchTemplateGroups together), the hits that rise most above their template's other
  // top-level positions first (RisePercent in matcher.cpp), over all templates: refining
  // costs far more than scoring, and near a part thousands of templates pass the top-level
  // threshold at several positions. Scene-Patch with 5 blocks found as many targets with 2000
  // shared as with 1000 per block (up to 5000), on four synthetic scene sets.
  int max_refinements = 2000;
  TemplateSearchMode search = TemplateSearchMode::kTree;
  // Tree searches: the share of clusters whose members are all scored, best representatives
  // first. 1 scores every template, as the flat search does.
  float tree_descend = 0.15f;
  // The refinement budget of a call in which some search goes through its view tree: the tree
  // scores only the views near the best representatives, so fewer hits of far views crowd the
  // budget. On full-sphere archives of two objects (docs/RESULTS.md) 1500 found what 2000 did
  // in 6 % less time per frame; 1000 lost targets.
  int tree_refinements = 1500;
  // Searches with occluders (TemplateSearch::occluders): a match needs at least this share of its
  // features off the occluders, and its similarity is that of those visible features.
  float min_visible_share = 0.5f;
  SimdPath simd = SimdPath::kAuto;

  void Validate() const;  // throws Error naming the bad field
};

struct RawMatch {
  int x = 0;  // level-0 top-left of the template box in scene pixels
  int y = 0;
  // At level 0: 100 * score / (4 * usable features), over the visible features only where the
  // search had occluders.
  float similarity_percent = 0.0f;
  std::uint32_t template_id = 0;
  float visible_share = 1.0f;  // of the usable level-0 features, those off occluders

  bool operator==(const RawMatch&) const = default;
};

// A scene ready for matching: every pyramid level spread and turned into response maps once,
// then shared (read-only, thread-safe) by all templates. The linear memories of a level are built
// on first use: only the levels where templates are scored on the whole grid (their top level)
// need them, and linearizing full resolution would cost about half of the preparation.
class PreparedScene {
 public:
  PreparedScene();  // no levels: matches nothing
  ~PreparedScene();
  PreparedScene(PreparedScene&&) noexcept;
  PreparedScene& operator=(PreparedScene&&) noexcept;

  // quantized[level][ModalityIndex(modality)]: CV_8UC1 bitmasks from the features stage (level k
  // at 1/2^k resolution); an absent modality is an empty Mat. spread_px[level]: LineMOD's T
  // (FeatureOptions::spread_px). Throws Error for fewer T than levels or invalid images.
  PreparedScene(const std::vector<std::array<cv::Mat, kModalityCount>>& quantized,
                const std::vector<int>& spread_px, SimdPath simd = SimdPath::kAuto);
  // Levels already turned into response maps (BuildSceneResponses), level 0 first; the linear
  // memories of those not yet linearized are built on first use as above.
  explicit PreparedScene(std::vector<SceneLevel> levels);

  int LevelCount() const { return static_cast<int>(levels_.size()); }
  // The level's responses (its linear memories only if already built).
  const SceneLevel& Level(int level) const;
  // The level with its linear memories, built on the first call (thread-safe; concurrent callers
  // help, so calling from inside oneTBB tasks is fine).
  const SceneLevel& LinearizedLevel(int level) const;

 private:
  struct LazyLevel;
  std::vector<std::unique_ptr<LazyLevel>> levels_;
};

// Matches every template (status kTooFewFeatures ones are skipped) against the scene, in two
// passes. First, per template over the levels both it and the scene have, every valid grid
// position of the top level is scored (all modalities' features together) and the positions at
// or above the threshold are kept (at most max_candidates_per_template). Second, the best of
// those hits over all templates (at most max_refinements, ranked by how far each rises above its
// template's other scored positions: RisePercent in matcher.cpp) are refined
// pixel by pixel at the top level within their grid cell, then at each lower level within +-T
// of the upscaled position (the best spread score wins; ties go to the best pixel-exact
// alignment, see ExactAlignmentScore); matches at or above the threshold at level 0 survive,
// then non-maximum suppression (MatchOptions::nms_radius_px). Both passes run in parallel
// (oneTBB).
//
// candidate_points (level-0 pixels): when given, only top-level grid positions that put the
// template's ANCHOR within candidate_radius_px of a point are scored; an empty list matches
// nothing. The anchor is box top-left + TemplateRecord::centre_offset_px (the projection of the
// object's sphere centre, where coarse positioning aims), or the box centre when that offset is
// zero.
//
// Deterministic: sorted by similarity (descending; with occluders, the similarity with the
// hidden features credited Occluders::hidden_credit), then template id, then y, then x.
// Throws Error for invalid options or a template with invalid features (naming its id).
std::vector<RawMatch> MatchTemplates(const PreparedScene& scene,
                                     std::span<const TemplateRecord> templates,
                                     const MatchOptions& options,
                                     const std::vector<cv::Point>* candidate_points = nullptr,
                                     int candidate_radius_px = 0);

// Several template sets, each searched around its own candidate points (nullptr: everywhere),
// in one call: as MatchTemplates over their union, with one refinement budget, one ranking and
// one suppression. Scene-Patch matches each depth layer's templates around the points of its
// kept blocks this way.
//
// With view clusters over `templates` (templates/view_clusters.h), the search first scores each
// cluster's representative at the top level with a threshold lowered by
// kRepresentativeMarginPercent, then every member of the best MatchOptions::tree_descend share
// of the clusters (by their representative's best top-level similarity); the rest as above.
//
// With occluders (match/occluders.h: where the scene lies in front of the object), the search's
// templates are ranked on its scene with partial credit for hidden features, and at level 0 the
// hidden features are counted out: a match needs MatchOptions::min_visible_share of its
// features visible and the threshold over those.
//
// Scoring reads each template's extent and feature counts from its facts (TemplateFactsOf):
// a caller that searches the same templates frame after frame works them out once and passes
// them; a search without them gets them worked out on every call.
struct Occluders;
using TemplateFacts = std::vector<TemplateLevelFacts>;  // per pyramid level, level 0 first
struct TemplateSearch {
  std::span<const TemplateRecord> templates;
  const std::vector<cv::Point>* candidate_points = nullptr;
  std::span<const ViewCluster> clusters;      // empty: every template is scored
  const Occluders* occluders = nullptr;       // nullptr: none
  std::span<const TemplateFacts> facts = {};  // parallel to `templates`, or empty
};
// LevelFacts of every level; throws Error naming the template for invalid features. With the
// scene's spread per pyramid level (`spread_px`, FeatureOptions::spread_px), the top level, the
// one scored on the grid, gets its grid features (about 4 bytes per feature).
TemplateFacts TemplateFactsOf(const TemplateRecord& record, std::span<const int> spread_px = {});
// The facts of each template, in their order (in parallel).
std::vector<TemplateFacts> TemplateFactsOf(std::span<const TemplateRecord> templates,
                                           std::span<const int> spread_px = {});
inline constexpr float kRepresentativeMarginPercent = 20.0f;
std::vector<RawMatch> MatchTemplateGroups(const PreparedScene& scene,
                                          std::span<const TemplateSearch> searches,
                                          const MatchOptions& options, int candidate_radius_px = 0);

}  // namespace layermod
