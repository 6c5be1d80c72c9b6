// SPDX-License-Identifier: MIT
#pragma once

// Typed reading of the BOP JSON files. Every failure is a FormatError that names the file and
// the entry ("'.../scene_gt.json': image 3, instance 0: 'cam_R_m2c' must be 9 numbers").

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/pose.h"
#include "util/quoted.h"

namespace layermod::bop_internal {

using layermod::Quoted;

// A JSON file and the place inside it, for error messages.
struct JsonContext {
  std::filesystem::path file;
  std::string where;  // "image 3, instance 0" or "" for the root

  [[noreturn]] void Fail(const std::string& problem) const;
  JsonContext Inside(const std::string& place) const;
};

// Parses a whole file. IoError when it cannot be read, FormatError when it is not JSON or its
// root is not an object.
nlohmann::json ParseJsonObjectFile(const std::filesystem::path& path);

// The integer value of an object key such as "42" (BOP keys images and objects by id).
int ParseIdKey(const std::string& key, const JsonContext& context);

const nlohmann::json& Field(const nlohmann::json& object, const char* key,
                            const JsonContext& context);
double NumberField(const nlohmann::json& object, const char* key, const JsonContext& context);
int IntField(const nlohmann::json& object, const char* key, const JsonContext& context);
// Exactly `count` finite numbers.
std::vector<double> NumbersField(const nlohmann::json& object, const char* key, std::size_t count,
                                 const JsonContext& context);

// cam_R_m2c (9 numbers, row-major) and cam_t_m2c (3 numbers, mm).
Pose PoseFields(const nlohmann::json& object, const char* rotation_key, const char* translation_key,
                const JsonContext& context);
// A row-major 4x4 rigid transform (models_info symmetries).
Pose PoseFrom4x4(const std::vector<double>& values);
std::vector<double> PoseTo4x4(const Pose& pose);

nlohmann::ordered_json RotationJson(const Eigen::Matrix3d& rotation);
nlohmann::ordered_json VectorJson(const Eigen::Vector3d& vector);

// Serialises with one space of indent per level (as BOP does); numbers keep their shortest
// exact form, so poses read back bit for bit.
std::string DumpJson(const nlohmann::json& json);
std::string DumpJson(const nlohmann::ordered_json& json);

}  // namespace layermod::bop_internal
