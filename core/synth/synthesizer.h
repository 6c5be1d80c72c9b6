// SPDX-License-Identifier: MIT
#pragma once

// The synthetic RGB-D scene generator: N images of target objects standing on a table among
// clutter, seen by a Kinect-like sensor, written as a BOP dataset with exact ground truth.

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include "dataset/bop.h"
#include "synth/model_library.h"
#include "synth/synth_options.h"
#include "util/job.h"

namespace layermod {

// Everything the images of a run share, loaded once.
struct SynthContext {
  SynthOptions options;
  std::map<std::int32_t, SynthModel> models;  // the targets and the clutter candidates
  std::vector<std::filesystem::path> backgrounds;
};

// Validates the options and loads the models (targets, plus every other model of the folder
// when there is clutter) and the list of background images. Throws Error (options, unknown
// object id), IoError (missing folders, unreadable files), FormatError (bad mesh or JSON).
SynthContext PrepareSynthesis(const SynthOptions& options);

// One generated image with what the tests and the summary need beyond the BOP frame.
struct SynthFrame {
  // Sensor colour and depth; gt[0] is the target (unless absent), then further instances of it
  // and the clutter models.
  BopFrame frame;
  cv::Mat clean_depth_mm;  // the composited depth before the sensor model
  // CV_16S: which placed item is seen at each pixel (items 0..gt.size()-1 are the annotated
  // models in gt order, higher indices primitives; negative: table or nothing).
  cv::Mat item_index;
  std::int32_t target_id = 0;
  bool target_present = true;  // false for the images without it (SynthOptions::absent_fraction)
  double target_distance_mm = 0.0;  // camera centre to the target's sphere centre
  double target_visibility = 0.0;
  int clutter_models = 0;
  int primitives = 0;
};

// Image `index` of the run (scene 1, image id `index`): deterministic for (options.seed, index),
// independent of the other images. Thread-safe.
SynthFrame SynthesizeFrame(const SynthContext& context, int index);

struct SynthSummary {
  std::filesystem::path out_dir;
  int images = 0;
  std::map<std::int32_t, int> images_per_target;
  double min_distance_mm = 0.0;
  double max_distance_mm = 0.0;
  double min_visibility = 0.0;
  double mean_visibility = 0.0;  // of the images with the target
  int images_without_target = 0;
  double seconds = 0.0;
};

// Generates options.scenes images in parallel and writes the BOP dataset options.out_dir:
// test/000001/{rgb,depth}/, scene_camera.json, scene_gt.json, scene_gt_info.json, camera.json,
// models/ (the used models and their models_info.json) and test_targets_bop19.json. The dataset
// is built in a temporary folder beside out_dir and renamed into place at the end, so a
// cancelled (throws Cancelled) or failed run leaves nothing behind. out_dir must be absent or
// an empty folder.
SynthSummary SynthesizeScenes(const SynthOptions& options, const JobControl& job = {});

}  // namespace layermod
