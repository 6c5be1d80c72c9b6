// SPDX-License-Identifier: MIT
#include "eval/eval_model.h"

#include <string>

#include "dataset/bop.h"
#include "dataset/models_info.h"
#include "mesh/model.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

std::vector<Eigen::Vector3d> ModelVertices(const fs::path& ply) {
  const Model model = LoadModel(ply);
  std::vector<Eigen::Vector3d> points;
  points.reserve(model.mesh.n_vertices());
  for (const auto vertex : model.mesh.vertices()) {
    const auto& p = model.mesh.point(vertex);
    points.emplace_back(p[0], p[1], p[2]);
  }
  return points;
}

}  // namespace

EvalModel::EvalModel(std::int32_t id, double diameter, bool is_symmetric,
                     std::vector<Eigen::Vector3d> model_points)
    : obj_id(id), diameter_mm(diameter), symmetric(is_symmetric), points(std::move(model_points)) {
  if (!(diameter_mm > 0.0)) {
    throw Error("object " + std::to_string(obj_id) + ": the diameter must be positive");
  }
  tree = std::make_shared<const PointKdTree>(points);
}

fs::path FindBopModelsDir(const fs::path& dataset_or_split_dir) {
  const fs::path inside = dataset_or_split_dir / "models";
  const fs::path beside = (dataset_or_split_dir / ".." / "models").lexically_normal();
  std::error_code ec;
  for (const fs::path& dir : {inside, beside}) {
    if (fs::is_regular_file(dir / "models_info.json", ec)) return dir;
  }
  throw IoError(Quoted(dataset_or_split_dir) + ": no models/models_info.json in it or beside it (" +
                Quoted(inside) + ", " + Quoted(beside) + ")");
}

std::map<std::int32_t, EvalModel> LoadEvalModels(const fs::path& models_dir,
                                                 const std::vector<std::int32_t>& obj_ids) {
  const fs::path info_file = models_dir / "models_info.json";
  const std::map<int, ModelInfo> infos = LoadModelsInfo(info_file);
  std::map<std::int32_t, EvalModel> models;
  for (const std::int32_t obj_id : obj_ids) {
    const auto info = infos.find(obj_id);
    if (info == infos.end()) {
      throw FormatError(Quoted(info_file) + ": no entry for object " + std::to_string(obj_id));
    }
    models.emplace(obj_id, EvalModel(obj_id, info->second.diameter_mm, info->second.IsSymmetric(),
                                     ModelVertices(models_dir / BopModelFileName(obj_id))));
  }
  return models;
}

}  // namespace layermod
