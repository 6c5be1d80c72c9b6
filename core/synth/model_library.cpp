// SPDX-License-Identifier: MIT
#include "synth/model_library.h"
#include "util/quoted.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <regex>
#include <set>
#include <string>

#include "dataset/bop.h"
#include "mesh/model.h"
#include "util/error.h"
#include "util/file_names.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

std::vector<Eigen::Vector3d> Positions(const RenderMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(mesh.positions.size());
  for (const Eigen::Vector3f& p : mesh.positions) points.push_back(p.cast<double>());
  return points;
}

}  // namespace

std::map<std::int32_t, fs::path> ListModelFiles(const fs::path& models_dir) {
  std::error_code ec;
  if (!fs::is_directory(models_dir, ec)) {
    throw IoError(Quoted(models_dir) + ": models folder does not exist");
  }
  static const std::regex kModelName(R"(obj_(\d{1,9})\.ply)", std::regex::icase);
  std::map<std::int32_t, fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(models_dir, ec)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, match, kModelName) && entry.is_regular_file(ec)) {
      files[std::stoi(match[1].str())] = entry.path();
    }
  }
  if (ec) throw IoError(Quoted(models_dir) + ": cannot list the folder (" + ec.message() + ")");
  if (files.empty()) {
    throw IoError(Quoted(models_dir) + ": no model files (BOP names them obj_000001.ply, ...)");
  }
  return files;
}

std::map<std::int32_t, fs::path> ModelFilesFor(const fs::path& models,
                                               const std::vector<std::int32_t>& obj_ids) {
  std::error_code ec;
  if (!fs::is_regular_file(models, ec)) return ListModelFiles(models);
  const std::set<std::int32_t> ids(obj_ids.begin(), obj_ids.end());
  if (ids.size() != 1) {
    throw Error("a single model file " + Quoted(models) + " is one object: give one object id");
  }
  if (LowercaseExtension(models) != ".ply") {
    throw Error(Quoted(models) + ": a single model file must be a PLY file (BOP's model format)");
  }
  return {{*ids.begin(), models}};
}

ModelInfo ComputeModelInfo(std::int32_t obj_id, const RenderMesh& mesh) {
  const std::vector<Eigen::Vector3d> points = Positions(mesh);
  ModelInfo info;
  info.obj_id = obj_id;
  info.diameter_mm = PointSetDiameter(points);
  if (points.empty()) return info;
  Eigen::Vector3d low = points[0];
  Eigen::Vector3d high = points[0];
  for (const Eigen::Vector3d& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  info.min = low;
  info.size = high - low;
  return info;
}

std::map<std::int32_t, SynthModel> LoadSynthModels(const fs::path& models_dir,
                                                   const std::map<std::int32_t, fs::path>& files,
                                                   const std::vector<std::int32_t>& ids) {
  for (const std::int32_t id : ids) {
    if (files.count(id) == 0) {
      throw Error("object " + std::to_string(id) + " has no model in " + Quoted(models_dir) +
                  " (expected " + BopModelFileName(id) + ")");
    }
  }
  std::map<int, ModelInfo> source_infos;
  const fs::path info_path = models_dir / "models_info.json";
  std::error_code ec;
  if (fs::is_regular_file(info_path, ec)) source_infos = LoadModelsInfo(info_path);

  std::vector<SynthModel> loaded(ids.size());
  tbb::parallel_for(std::size_t{0}, ids.size(), [&](std::size_t i) {
    const Model model = LoadModel(files.at(ids[i]));
    SynthModel& synth = loaded[i];
    synth.obj_id = ids[i];
    synth.path = files.at(ids[i]);
    synth.mesh = ToRenderMesh(model);
    synth.sphere = model.sphere;
    const auto source = source_infos.find(ids[i]);
    synth.info =
        source != source_infos.end() ? source->second : ComputeModelInfo(ids[i], synth.mesh);
  });
  std::map<std::int32_t, SynthModel> models;
  for (SynthModel& model : loaded) models[model.obj_id] = std::move(model);
  return models;
}

}  // namespace layermod
