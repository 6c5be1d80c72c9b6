// SPDX-License-Identifier: MIT
#include <layermod/training.h>

#include <nlohmann/json.hpp>

#include "api/archive_access.h"
#include "geometry/units.h"
#include "mesh/model.h"
#include "pipeline/training.h"
#include "templates/training_profile.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/job.h"

namespace layermod::api {
namespace {

TrainingProfile Profile(const TrainOptions& options) {
  if (!options.profile_json.empty()) {
    const nlohmann::json json = nlohmann::json::parse(options.profile_json, nullptr, false);
    if (json.is_discarded()) throw FormatError("training profile: not valid JSON");
    return TrainingProfileFromJson(json);
  }
  if (!options.profile_file.empty()) return LoadTrainingProfile(options.profile_file);
  return TrainingProfile{};
}

}  // namespace

// What `layermod train` does (README "train"), without the progress bar and the dry run.
Archive Train(const TrainOptions& options, const ProgressCallback& progress,
              const std::atomic<bool>* cancel) {
  TrainingRequest request;
  request.obj_id = options.obj_id;
  request.name = options.name;
  request.camera = ToCore(options.camera);
  request.profile = Profile(options);
  request.threads = options.threads;
  request.max_render_triangles = options.max_render_triangles;
  request.camera.Validate();
  if (!options.out.empty()) CheckWritableTarget(options.out);  // fail before the work

  LoadModelOptions load_options;
  load_options.units = ParseLengthUnit(options.units);
  const Model model = LoadModel(options.model, load_options);
  if (request.name.empty()) request.name = model.source.stem().string();
  PlanTraining(model, request);  // refuses runs too large for this machine before rendering

  CancelToken token;
  const JobControl job(
      [&](std::size_t done, std::size_t total, std::string_view stage) {
        if (progress) progress(done, total, stage);
        if (cancel != nullptr && cancel->load()) token.Cancel();
      },
      &token);
  if (cancel != nullptr && cancel->load()) throw Cancelled();
  TrainingResult result = TrainTemplates(model, request, job);
  job.ThrowIfCancelled();
  if (!options.out.empty()) WriteArchive(options.out, result.archive);
  return ArchiveAccess::Wrap(std::make_shared<const TemplateArchive>(std::move(result.archive)));
}

}  // namespace layermod::api
