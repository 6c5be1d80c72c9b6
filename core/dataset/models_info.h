// SPDX-License-Identifier: MIT
#pragma once

// BOP's models/models_info.json: per object the diameter (largest distance between two
// vertices, mm), the bounding box, and the symmetries used by ADD-S style metrics.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include "geometry/pose.h"

namespace layermod {

// A continuous rotational symmetry: any rotation about `axis` through `offset` (model frame, mm).
struct ContinuousSymmetry {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

struct ModelInfo {
  std::int32_t obj_id = 0;
  double diameter_mm = 0.0;
  Eigen::Vector3d min = Eigen::Vector3d::Zero();   // bounding box corner (mm)
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // bounding box extent (mm)
  std::vector<Pose> symmetries_discrete;           // model-to-model transforms, t in mm
  std::vector<ContinuousSymmetry> symmetries_continuous;

  bool IsSymmetric() const {
    return !symmetries_discrete.empty() || !symmetries_continuous.empty();
  }
};

// Reads models_info.json, keyed by object id. Throws IoError/FormatError naming the file, the
// object and the field.
std::map<int, ModelInfo> LoadModelsInfo(const std::filesystem::path& models_info_json);

// Writes models_info.json atomically (BOP layout: diameter, min_x.., size_x.., symmetries as
// row-major 4x4 matrices / {axis, offset}). Throws IoError.
void WriteModelsInfo(const std::filesystem::path& models_info_json,
                     const std::map<int, ModelInfo>& infos);

// The largest distance between two of `points` (mm): the BOP diameter. Exact; fast for meshes
// of a few hundred thousand vertices because only points far from the centre can be on the
// diametral pair. Returns 0 for fewer than two points.
double PointSetDiameter(const std::vector<Eigen::Vector3d>& points);

}  // namespace layermod
