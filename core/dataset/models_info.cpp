// SPDX-License-Identifier: MIT
#include "dataset/models_info.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>

#include "dataset/bop_json.h"
#include "util/atomic_file.h"

namespace layermod {
namespace fs = std::filesystem;
using bop_internal::JsonContext;

namespace {

constexpr double kRotationTolerance = 1e-2;  // BOP rounds its symmetry matrices to 6 digits

void ReadDiscreteSymmetries(const nlohmann::json& entry, const JsonContext& context,
                            ModelInfo& info) {
  const nlohmann::json& list = bop_internal::Field(entry, "symmetries_discrete", context);
  if (!list.is_array()) context.Fail("'symmetries_discrete' must be a list of 4x4 matrices");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const JsonContext item = context.Inside("symmetries_discrete[" + std::to_string(i) + "]");
    const nlohmann::json wrapper = {{"matrix", list[i]}};
    const Pose pose =
        bop_internal::PoseFrom4x4(bop_internal::NumbersField(wrapper, "matrix", 16, item));
    const double error = (pose.R * pose.R.transpose() - Eigen::Matrix3d::Identity()).norm();
    if (error > kRotationTolerance) item.Fail("the 3x3 part is not a rotation");
    info.symmetries_discrete.push_back(pose);
  }
}

void ReadContinuousSymmetries(const nlohmann::json& entry, const JsonContext& context,
                              ModelInfo& info) {
  const nlohmann::json& list = bop_internal::Field(entry, "symmetries_continuous", context);
  if (!list.is_array()) context.Fail("'symmetries_continuous' must be a list");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const JsonContext item = context.Inside("symmetries_continuous[" + std::to_string(i) + "]");
    const std::vector<double> axis = bop_internal::NumbersField(list[i], "axis", 3, item);
    const std::vector<double> offset = bop_internal::NumbersField(list[i], "offset", 3, item);
    ContinuousSymmetry symmetry;
    symmetry.axis = {axis[0], axis[1], axis[2]};
    symmetry.offset = {offset[0], offset[1], offset[2]};
    if (symmetry.axis.norm() < 1e-9) item.Fail("'axis' must not be zero");
    symmetry.axis.normalize();
    info.symmetries_continuous.push_back(symmetry);
  }
}

ModelInfo ReadModelInfo(int obj_id, const nlohmann::json& entry, const JsonContext& context) {
  ModelInfo info;
  info.obj_id = obj_id;
  info.diameter_mm = bop_internal::NumberField(entry, "diameter", context);
  if (info.diameter_mm <= 0.0) context.Fail("'diameter' must be positive");
  const char* min_keys[] = {"min_x", "min_y", "min_z"};
  const char* size_keys[] = {"size_x", "size_y", "size_z"};
  for (int axis = 0; axis < 3; ++axis) {
    // The box is informative only: some datasets omit it.
    if (entry.contains(min_keys[axis])) {
      info.min[axis] = bop_internal::NumberField(entry, min_keys[axis], context);
    }
    if (entry.contains(size_keys[axis])) {
      info.size[axis] = bop_internal::NumberField(entry, size_keys[axis], context);
    }
  }
  if (entry.contains("symmetries_discrete")) ReadDiscreteSymmetries(entry, context, info);
  if (entry.contains("symmetries_continuous")) ReadContinuousSymmetries(entry, context, info);
  return info;
}

nlohmann::ordered_json ModelInfoJson(const ModelInfo& info) {
  nlohmann::ordered_json entry = {
      {"diameter", info.diameter_mm}, {"min_x", info.min.x()},   {"min_y", info.min.y()},
      {"min_z", info.min.z()},        {"size_x", info.size.x()}, {"size_y", info.size.y()},
      {"size_z", info.size.z()},
  };
  if (!info.symmetries_discrete.empty()) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const Pose& pose : info.symmetries_discrete) {
      list.push_back(bop_internal::PoseTo4x4(pose));
    }
    entry["symmetries_discrete"] = list;
  }
  if (!info.symmetries_continuous.empty()) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ContinuousSymmetry& symmetry : info.symmetries_continuous) {
      list.push_back({{"axis", bop_internal::VectorJson(symmetry.axis)},
                      {"offset", bop_internal::VectorJson(symmetry.offset)}});
    }
    entry["symmetries_continuous"] = list;
  }
  return entry;
}

// A lower bound of the diameter from a few farthest-point hops (usually the exact value).
double FarthestHopsLowerBound(const std::vector<Eigen::Vector3d>& points) {
  std::size_t from = 0;
  double best = 0.0;
  for (int hop = 0; hop < 4; ++hop) {
    std::size_t farthest = from;
    double farthest_distance = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double distance = (points[i] - points[from]).squaredNorm();
      if (distance > farthest_distance) {
        farthest_distance = distance;
        farthest = i;
      }
    }
    best = std::max(best, std::sqrt(farthest_distance));
    from = farthest;
  }
  return best;
}

}  // namespace

std::map<int, ModelInfo> LoadModelsInfo(const fs::path& models_info_json) {
  const nlohmann::json json = bop_internal::ParseJsonObjectFile(models_info_json);
  const JsonContext file{models_info_json, ""};
  std::map<int, ModelInfo> infos;
  for (const auto& [key, entry] : json.items()) {
    const int obj_id = bop_internal::ParseIdKey(key, file);
    infos[obj_id] = ReadModelInfo(obj_id, entry, file.Inside("object " + key));
  }
  return infos;
}

void WriteModelsInfo(const fs::path& models_info_json, const std::map<int, ModelInfo>& infos) {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const auto& [obj_id, info] : infos) json[std::to_string(obj_id)] = ModelInfoJson(info);
  WriteFileAtomically(models_info_json, bop_internal::DumpJson(json));
}

double PointSetDiameter(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 2) return 0.0;
  double best = FarthestHopsLowerBound(points);
  Eigen::Vector3d low = points[0];
  Eigen::Vector3d high = points[0];
  for (const Eigen::Vector3d& point : points) {
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  const Eigen::Vector3d centre = 0.5 * (low + high);
  // |p - q| <= |p - c| + |q - c|: visit points by decreasing distance to c and stop as soon as
  // no remaining pair can beat the best distance found.
  std::vector<double> radius(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) radius[i] = (points[i] - centre).norm();
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&radius](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double radius_i = radius[order[i]];
    if (2.0 * radius_i <= best) break;
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      if (radius_i + radius[order[j]] <= best) break;
      best = std::max(best, (points[order[i]] - points[order[j]]).norm());
    }
  }
  return best;
}

}  // namespace layermod
