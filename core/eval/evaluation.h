// SPDX-License-Identifier: MIT
#pragma once

// `layermod eval` as one call: the dataset's frames and models for the archives' objects, the
// detector as the method under test, and the summary.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "eval/eval_frames.h"
#include "eval/eval_runner.h"
#include "eval/eval_summary.h"
#include "pipeline/detector.h"

namespace layermod {

struct EvalPlan {
  EvalDataset dataset;
  std::vector<EvalFrame> frames;
};

// Reads the scenes of `dataset_dir` (a BOP root or split folder), the models of `obj_ids` from
// the dataset's models/ folder, and selects the frames. With `needs_depth`, refuses (Error naming
// the scene folder) a selected scene without depth images. Throws Error for a --scene the
// dataset does not have, IoError/FormatError for unreadable files.
EvalPlan PlanEvaluation(const std::filesystem::path& dataset_dir,
                        const std::vector<std::int32_t>& obj_ids,
                        const FrameSelectionOptions& selection, bool needs_depth);

// Whether a detection mode reads the depth image.
bool ModeNeedsDepth(DetectionMode mode);

// The detector as a method: Detect() on the frame's colour, depth and camera.
EvalMethod DetectorMethod(const Detector& detector, const DetectorOptions& options);

// The targets no template of the detector's archives covers (every annotated instance outside its
// object's ViewEnvelope), by (scene id, image id, object id), with the reason of the first.
using EnvelopeMisses = std::map<std::tuple<int, int, std::int32_t>, std::string>;
EnvelopeMisses FindEnvelopeMisses(const Detector& detector, const EvalPlan& plan);

// Marks the outcomes of those targets (outside_envelope, envelope_note).
void MarkEnvelopeMisses(const EnvelopeMisses& misses, MethodRun& run);

// The object ids of the detector's archives, ascending.
std::vector<std::int32_t> DetectorObjectIds(const Detector& detector);

struct Evaluation {
  MethodRun run;
  MethodSummary summary;
};

// Plans, runs `detector` with `options` on every selected frame, and summarises.
Evaluation Evaluate(const Detector& detector, const DetectorOptions& options,
                    const std::filesystem::path& dataset_dir,
                    const FrameSelectionOptions& selection, const EvalMetricOptions& metrics,
                    const JobControl& job = {});

}  // namespace layermod
