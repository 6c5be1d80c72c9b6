// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "mesh/model.h"
#include "templates/archive.h"
#include "templates/training_profile.h"
#include "util/job.h"

namespace layermod {

// What to train: one object seen by one camera under one profile.
struct TrainingRequest {
  std::int32_t obj_id = 1;
  std::string name;
  PinholeCamera camera;
  TrainingProfile profile;
  int threads = 0;  // 0: all hardware threads
  // Meshes with more triangles are simplified (surface moved by at most the error) before
  // rendering; the archive keeps the simplified mesh for pose refinement. 0: never simplify.
  std::size_t max_render_triangles = 12000;
  double max_simplification_error_mm = 0.5;

  void Validate() const;  // throws Error naming the bad field
};

// Sizes of a training run, known before any rendering.
struct TrainingPlan {
  double radius_mm = 0.0;
  std::vector<double> layer_depths_mm;
  std::vector<ViewAngles> views;
  std::size_t TemplateCount() const { return layer_depths_mm.size() * views.size(); }
  // Rough memory the finished archive takes in RAM (bytes), to refuse absurd requests early.
  std::size_t EstimatedBytes(const FeatureOptions& features) const;
};

// Rough memory `templates` templates take in RAM (bytes).
std::size_t EstimatedTemplateBytes(std::size_t templates, const FeatureOptions& features);

// The most a training run may allocate for its templates on this machine: a third of physical
// memory (the archive is serialised once more while it is written), at most 8 GiB.
std::size_t TrainingMemoryLimitBytes();

struct TrainingSummary {
  double radius_mm = 0.0;
  int layers = 0;
  std::size_t templates = 0;
  std::size_t weak_templates = 0;  // fewer than FeatureOptions::min_features
  double seconds = 0.0;
  double TemplatesPerSecond() const { return seconds > 0 ? templates / seconds : 0.0; }
};

struct TrainingResult {
  TemplateArchive archive;
  TrainingSummary summary;
};

// Layers and views for `model` under `request` (cheap; the studio shows it live). Throws Error
// before sampling anything when the run would need more than TrainingMemoryLimitBytes().
TrainingPlan PlanTraining(const Model& model, const TrainingRequest& request);

// Renders every view at every depth layer and extracts its LineMOD template, in parallel.
// Reports progress per template and throws Cancelled when `job` is cancelled.
TrainingResult TrainTemplates(const Model& model, const TrainingRequest& request,
                              const JobControl& job = {});

}  // namespace layermod
