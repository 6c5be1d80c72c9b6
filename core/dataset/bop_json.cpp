// SPDX-License-Identifier: MIT
#include "dataset/bop_json.h"

#include <charconv>
#include <cmath>
#include <limits>

#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod::bop_internal {

void JsonContext::Fail(const std::string& problem) const {
  std::string message = Quoted(file) + ": ";
  if (!where.empty()) message += where + ": ";
  throw FormatError(message + problem);
}

JsonContext JsonContext::Inside(const std::string& place) const {
  return {file, where.empty() ? place : where + ", " + place};
}

nlohmann::json ParseJsonObjectFile(const std::filesystem::path& path) {
  const std::string text = ReadFileBytes(path);
  nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  const JsonContext context{path, ""};
  if (json.is_discarded()) context.Fail("malformed JSON");
  if (!json.is_object()) context.Fail("the top level is not a JSON object");
  return json;
}

int ParseIdKey(const std::string& key, const JsonContext& context) {
  int id = -1;
  const char* end = key.data() + key.size();
  const auto [ptr, ec] = std::from_chars(key.data(), end, id);
  if (key.empty() || ec != std::errc() || ptr != end || id < 0) {
    context.Fail("key '" + key + "' is not a non-negative integer id");
  }
  return id;
}

const nlohmann::json& Field(const nlohmann::json& object, const char* key,
                            const JsonContext& context) {
  if (!object.is_object()) context.Fail("expected a JSON object");
  const auto it = object.find(key);
  if (it == object.end()) context.Fail(Quoted(std::string_view(key)) + " is missing");
  return *it;
}

double NumberField(const nlohmann::json& object, const char* key, const JsonContext& context) {
  const nlohmann::json& value = Field(object, key, context);
  if (!value.is_number()) context.Fail(Quoted(std::string_view(key)) + " must be a number");
  const double number = value.get<double>();
  if (!std::isfinite(number)) context.Fail(Quoted(std::string_view(key)) + " must be finite");
  return number;
}

int IntField(const nlohmann::json& object, const char* key, const JsonContext& context) {
  const nlohmann::json& value = Field(object, key, context);
  const bool fits = value.is_number_integer() &&
                    value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                    value.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) context.Fail(Quoted(std::string_view(key)) + " must be an integer");
  return value.get<int>();
}

std::vector<double> NumbersField(const nlohmann::json& object, const char* key, std::size_t count,
                                 const JsonContext& context) {
  const nlohmann::json& value = Field(object, key, context);
  const std::string problem =
      Quoted(std::string_view(key)) + " must be " + std::to_string(count) + " numbers";
  if (!value.is_array() || value.size() != count) context.Fail(problem);
  std::vector<double> numbers;
  numbers.reserve(count);
  for (const nlohmann::json& element : value) {
    if (!element.is_number() || !std::isfinite(element.get<double>())) context.Fail(problem);
    numbers.push_back(element.get<double>());
  }
  return numbers;
}

Pose PoseFields(const nlohmann::json& object, const char* rotation_key, const char* translation_key,
                const JsonContext& context) {
  const std::vector<double> r = NumbersField(object, rotation_key, 9, context);
  const std::vector<double> t = NumbersField(object, translation_key, 3, context);
  Pose pose;
  for (std::size_t i = 0; i < 9; ++i) {
    pose.R(static_cast<int>(i / 3), static_cast<int>(i % 3)) = r[i];
  }
  pose.t = {t[0], t[1], t[2]};
  return pose;
}

Pose PoseFrom4x4(const std::vector<double>& values) {
  Pose pose;
  for (std::size_t row = 0; row < 3; ++row) {
    const auto r = static_cast<int>(row);
    for (std::size_t col = 0; col < 3; ++col) {
      pose.R(r, static_cast<int>(col)) = values[4 * row + col];
    }
    pose.t[r] = values[4 * row + 3];
  }
  return pose;
}

std::vector<double> PoseTo4x4(const Pose& pose) {
  std::vector<double> values(16, 0.0);
  for (std::size_t row = 0; row < 3; ++row) {
    const auto r = static_cast<int>(row);
    for (std::size_t col = 0; col < 3; ++col) {
      values[4 * row + col] = pose.R(r, static_cast<int>(col));
    }
    values[4 * row + 3] = pose.t[r];
  }
  values[15] = 1.0;
  return values;
}

nlohmann::ordered_json RotationJson(const Eigen::Matrix3d& rotation) {
  nlohmann::ordered_json values = nlohmann::ordered_json::array();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) values.push_back(rotation(row, col));
  }
  return values;
}

nlohmann::ordered_json VectorJson(const Eigen::Vector3d& vector) {
  return nlohmann::ordered_json::array({vector.x(), vector.y(), vector.z()});
}

std::string DumpJson(const nlohmann::json& json) { return json.dump(1) + "\n"; }
std::string DumpJson(const nlohmann::ordered_json& json) { return json.dump(1) + "\n"; }

}  // namespace layermod::bop_internal
