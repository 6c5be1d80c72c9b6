// SPDX-License-Identifier: MIT
#pragma once

// What the metrics need to know about one object: its points, diameter and whether it is
// symmetric (ADD-S instead of ADD), all from the dataset's models/ folder, as BOP does.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include "eval/point_search.h"

namespace layermod {

struct EvalModel {
  std::int32_t obj_id = 0;
  double diameter_mm = 0.0;             // models_info.json
  bool symmetric = false;               // models_info.json lists a discrete or continuous symmetry
  std::vector<Eigen::Vector3d> points;  // the model's vertices (mm)
  std::shared_ptr<const PointKdTree> tree;  // over `points`, for ADD-S

  // Builds the search tree. Throws Error for no points or a non-positive diameter.
  EvalModel(std::int32_t id, double diameter, bool is_symmetric,
            std::vector<Eigen::Vector3d> model_points);
};

// The models folder of a BOP dataset given its root or one of its split folders: `dir`/models or
// `dir`/../models, whichever has models_info.json. Throws IoError naming both places.
std::filesystem::path FindBopModelsDir(const std::filesystem::path& dataset_or_split_dir);

// Loads models_info.json and obj_NNNNNN.ply of each id. Throws FormatError for an id missing from
// models_info.json, IoError/FormatError for a missing or broken model file (naming it).
std::map<std::int32_t, EvalModel> LoadEvalModels(const std::filesystem::path& models_dir,
                                                 const std::vector<std::int32_t>& obj_ids);

}  // namespace layermod
