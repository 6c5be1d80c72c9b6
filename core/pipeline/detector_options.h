// SPDX-License-Identifier: MIT
// The one table of detector settings. Every field has a name (the JSON key; with '_' turned
// into '-' it is the command-line flag), a help line and a range. The CLI flags of `detect`,
// `eval` and `bench`, the studio's form and its saved settings, the detector profiles
// (`--detector-profile FILE`) and the eval/bench reports are all built from it, so a knob
// exists everywhere or nowhere.
#pragma once

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "pipeline/detector.h"

namespace layermod {

struct DetectorOptionField {
  std::string_view key;    // JSON key, e.g. "edge_upper"; flag "--edge-upper"
  std::string_view help;   // one line, with the unit
  std::string_view group;  // "matching", "coarse positioning", ... (the studio groups by it)
  double min = 0.0;        // inclusive range of numeric fields
  double max = 0.0;
};

// The command-line flag of a field: "--" + key with '_' -> '-'.
std::string OptionFlag(const DetectorOptionField& field);
// A range bound as the help and errors print it ("100", "0.5", "1e+07").
std::string FormatRange(double value);

// Settings chosen by name (the detection mode, the template search): their values in the order
// help texts and the studio list them, and each value's name.
template <typename T>
struct OptionChoices {
  static constexpr bool kIsChoice = false;
};
template <>
struct OptionChoices<DetectionMode> {
  static constexpr bool kIsChoice = true;
  static constexpr std::array kValues = {DetectionMode::kScenePatch, DetectionMode::kExhaustive,
                                         DetectionMode::kColorOnly};
  static std::string_view Name(DetectionMode mode) { return ModeName(mode); }
  static DetectionMode Parse(std::string_view text) { return ParseDetectionMode(text); }
};
template <>
struct OptionChoices<TemplateSearchMode> {
  static constexpr bool kIsChoice = true;
  static constexpr std::array kValues = {TemplateSearchMode::kTree, TemplateSearchMode::kFlat};
  static std::string_view Name(TemplateSearchMode search) { return SearchModeName(search); }
  static TemplateSearchMode Parse(std::string_view text) { return ParseSearchMode(text); }
};
template <>
struct OptionChoices<OcclusionMode> {
  static constexpr bool kIsChoice = true;
  static constexpr std::array kValues = {OcclusionMode::kAware, OcclusionMode::kIgnore};
  static std::string_view Name(OcclusionMode mode) { return OcclusionModeName(mode); }
  static OcclusionMode Parse(std::string_view text) { return ParseOcclusionMode(text); }
};
template <typename T>
inline constexpr bool kIsChoiceOption = OptionChoices<T>::kIsChoice;

// The names of a choice setting's values, in order.
template <typename T>
std::vector<std::string> ChoiceNames() {
  std::vector<std::string> names;
  names.reserve(OptionChoices<T>::kValues.size());
  for (T value : OptionChoices<T>::kValues) names.emplace_back(OptionChoices<T>::Name(value));
  return names;
}

// Calls visitor(field, value&) for every setting of `options`, in table order. `value` is an
// int&, float&, double& or a choice (kIsChoiceOption: DetectionMode&, TemplateSearchMode&,
// OcclusionMode&).
template <typename Options, typename Visitor>
void VisitDetectorOptions(Options& options, Visitor&& visitor) {
  using G = std::string_view;
  const G matching = "matching", coarse = "coarse positioning", regions = "region division",
          pose = "pose refinement", verify = "verification", output = "output";
  visitor(DetectorOptionField{"mode", "scene-patch, exhaustive or color-only", matching, 0, 0},
          options.mode);
  visitor(DetectorOptionField{"instances", "Detections kept per object", output, 1, 1000},
          options.max_instances);
  visitor(DetectorOptionField{"min_confidence",
                              "Detections less confident than this (0..1) are not reported", output,
                              0, 1},
          options.min_confidence);
  visitor(DetectorOptionField{"pose_candidates",
                              "Best raw matches per object that get a pose and a verification",
                              pose, 1, 1000},
          options.pose_candidates);
  visitor(
      DetectorOptionField{"threshold", "Match similarity threshold (percent)", matching, 1, 100},
      options.match.threshold_percent);
  visitor(DetectorOptionField{"nms_radius",
                              "Matches of one object closer than this are "
                              "duplicates (level-0 px)",
                              matching, 0, 1000},
          options.match.nms_radius_px);
  visitor(DetectorOptionField{"matches_per_location",
                              "Matches kept per neighbourhood of the NMS radius", matching, 1, 100},
          options.match.matches_per_location);
  visitor(DetectorOptionField{"max_matches", "Best matches kept after suppression", matching, 1,
                              100000},
          options.match.max_matches);
  visitor(DetectorOptionField{"candidates_per_template", "Top-level positions refined per template",
                              matching, 1, 100000},
          options.match.max_candidates_per_template);
  visitor(DetectorOptionField{"refinements",
                              "Top-level hits refined down the pyramid per object and frame",
                              matching, 1, 1e7},
          options.match.max_refinements);
  visitor(DetectorOptionField{"search",
                              "tree (best view clusters first, where layers have a view tree) "
                              "or flat (every view)",
                              matching, 0, 0},
          options.match.search);
  visitor(DetectorOptionField{"tree_descend",
                              "Share of view clusters searched in full in layers with a view "
                              "tree (1 = flat search)",
                              matching, 0.001, 1},
          options.match.tree_descend);
  visitor(DetectorOptionField{"tree_refinements",
                              "Top-level hits refined per object and frame where layers are "
                              "searched through their view tree",
                              matching, 1, 1e7},
          options.match.tree_refinements);
  visitor(DetectorOptionField{"occlusion",
                              "aware (features on what lies in front of the part are counted "
                              "out of its score) or ignore",
                              matching, 0, 0},
          options.occlusion);
  visitor(DetectorOptionField{"min_visible_share",
                              "Share of a match's features that must lie off occluders "
                              "(occlusion aware)",
                              matching, 0.01, 1},
          options.match.min_visible_share);
  visitor(DetectorOptionField{"blocks", "Scene blocks kept by coarse positioning (0 = all)", coarse,
                              0, 1000},
          options.coarse.max_blocks);
  visitor(DetectorOptionField{"edge_lower",
                              "Depth-edge test's lower factor: num_i >= factor x N_min (Eq. 5)",
                              coarse, 0, 10},
          options.coarse.lower_factor);
  visitor(DetectorOptionField{"edge_upper",
                              "Depth-edge test's upper factor: num_i <= factor x N_max (Eq. 5)",
                              coarse, 0, 10},
          options.coarse.upper_factor);
  visitor(DetectorOptionField{"point_step", "Spacing of detection points in a block (px)", coarse,
                              1, 256},
          options.coarse.point_step_px);
  visitor(DetectorOptionField{"hole_fill",
                              "Depth holes up to this wide are filled before edges "
                              "are counted (px)",
                              coarse, 0, 256},
          options.coarse.hole_fill_px);
  visitor(DetectorOptionField{"cell_size", "Region division's cell size (px)", regions, 1, 256},
          options.regions.cell_size_px);
  visitor(DetectorOptionField{"seed_step", "Region seeds every this many cells", regions, 1, 256},
          options.regions.seed_step_cells);
  visitor(DetectorOptionField{"depth_spread",
                              "A region's largest depth spread, Eq. 1 "
                              "(mm, 0 = the sphere radius)",
                              regions, 0, 1e5},
          options.regions.depth_spread_mm);
  visitor(DetectorOptionField{"max_layer_distance",
                              "Regions farther than this from every layer "
                              "are dropped (mm, 0 = the sphere radius)",
                              regions, 0, 1e5},
          options.regions.max_layer_distance_mm);
  visitor(DetectorOptionField{"min_block_cells", "Smaller regions are dropped (cells)", regions, 1,
                              1e6},
          options.regions.min_block_cells);
  visitor(DetectorOptionField{"icp_iterations", "ICP iterations at most", pose, 1, 1000},
          options.icp.max_iterations);
  visitor(
      DetectorOptionField{"icp_renders", "Visible-surface re-samplings during ICP", pose, 1, 100},
      options.icp.renders);
  visitor(DetectorOptionField{"icp_initial_gate", "ICP correspondence gate at the start (mm)", pose,
                              0, 1e4},
          options.icp.initial_max_distance_mm);
  visitor(DetectorOptionField{"icp_final_gate", "ICP correspondence gate at the end (mm)", pose, 0,
                              1e4},
          options.icp.final_max_distance_mm);
  visitor(DetectorOptionField{"icp_huber", "ICP robust loss scale (mm)", pose, 0, 1e4},
          options.icp.huber_mm);
  visitor(DetectorOptionField{"icp_sample_step", "ICP visible-surface sampling step (px)", pose, 1,
                              256},
          options.icp.sample_step_px);
  visitor(
      DetectorOptionField{"icp_convergence", "ICP stops when points move less (mm)", pose, 0, 1e3},
      options.icp.convergence_mm);
  visitor(DetectorOptionField{"icp_max_step", "Largest ICP translation step (mm)", pose, 0, 1e4},
          options.icp.max_step_mm);
  visitor(DetectorOptionField{"icp_max_step_deg", "Largest ICP rotation step (deg)", pose, 0, 180},
          options.icp.max_step_deg);
  visitor(
      DetectorOptionField{"icp_max_drift", "ICP is abandoned beyond this drift (mm)", pose, 0, 1e5},
      options.icp.max_drift_mm);
  visitor(DetectorOptionField{"icp_max_drift_deg", "ICP is abandoned beyond this drift (deg)", pose,
                              0, 180},
          options.icp.max_drift_deg);
  visitor(DetectorOptionField{"depth_tolerance", "Scene and model depth agree within this (mm)",
                              verify, 0, 1e4},
          options.verification.depth_tolerance_mm);
  visitor(DetectorOptionField{"min_inlier_ratio", "Depth inlier ratio a pose needs", verify, 0, 1},
          options.verification.min_depth_inlier_ratio);
  visitor(
      DetectorOptionField{"min_visible_ratio",
                          "Share of the silhouette the scene must not contradict", verify, 0, 1},
      options.verification.min_visible_ratio);
  visitor(
      DetectorOptionField{"hue_tolerance", "Hue difference still agreeing (deg)", verify, 0, 180},
      options.verification.hue_tolerance_deg);
  visitor(
      DetectorOptionField{"min_color_agreement",
                          "Colour agreement a pose needs (saturated models only)", verify, 0, 1},
      options.verification.min_color_agreement);
}

// Every field by name, for the studio and reports.
std::vector<DetectorOptionField> DetectorOptionFields();

// All fields, mode as its name ("scene-patch").
nlohmann::json DetectorOptionsToJson(const DetectorOptions& options);

// Fields present in `json` replace those of `base`; absent ones keep base's value. Throws
// FormatError naming `what` and the field for unknown keys, wrong types and out-of-range values.
DetectorOptions DetectorOptionsFromJson(const nlohmann::json& json, std::string_view what,
                                        DetectorOptions base = {});

// A detector profile file: a JSON object of fields (or {"detector": {...}}). Throws IoError or
// FormatError naming the file.
DetectorOptions ReadDetectorProfile(const std::filesystem::path& path, DetectorOptions base = {});
void WriteDetectorProfile(const std::filesystem::path& path, const DetectorOptions& options);

}  // namespace layermod
