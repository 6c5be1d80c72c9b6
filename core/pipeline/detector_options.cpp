// SPDX-License-Identifier: MIT
#include "pipeline/detector_options.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <type_traits>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

std::string Describe(std::string_view what, const DetectorOptionField& field) {
  return std::string(what) + " field '" + std::string(field.key) + "'";
}

template <typename T>
void ReadNumber(const nlohmann::json& value, const DetectorOptionField& field,
                std::string_view what, T& out) {
  if (!value.is_number()) throw FormatError(Describe(what, field) + " must be a number");
  const double number = value.get<double>();
  if (std::is_integral_v<T> && !value.is_number_integer()) {
    throw FormatError(Describe(what, field) + " must be an integer");
  }
  if (!std::isfinite(number) || number < field.min || number > field.max) {
    throw FormatError(Describe(what, field) + " must lie in [" + FormatRange(field.min) + ", " +
                      FormatRange(field.max) + "]");
  }
  out = static_cast<T>(number);
}

template <typename T>
void ReadChoice(const nlohmann::json& value, const DetectorOptionField& field,
                std::string_view what, T& out) {
  if (!value.is_string()) throw FormatError(Describe(what, field) + " must be a string");
  try {
    out = OptionChoices<T>::Parse(value.get<std::string>());
  } catch (const Error& error) {
    throw FormatError(Describe(what, field) + ": " + error.what());
  }
}

}  // namespace

std::string FormatRange(double value) {
  std::string text = nlohmann::json(value).dump();
  if (text.size() > 2 && text.ends_with(".0")) text.resize(text.size() - 2);
  return text;
}

std::string OptionFlag(const DetectorOptionField& field) {
  std::string flag = "--" + std::string(field.key);
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

std::vector<DetectorOptionField> DetectorOptionFields() {
  std::vector<DetectorOptionField> fields;
  DetectorOptions options;
  VisitDetectorOptions(options,
                       [&](const DetectorOptionField& field, auto&) { fields.push_back(field); });
  return fields;
}

nlohmann::json DetectorOptionsToJson(const DetectorOptions& options) {
  nlohmann::json json = nlohmann::json::object();
  VisitDetectorOptions(options, [&](const DetectorOptionField& field, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (kIsChoiceOption<T>) {
      json[std::string(field.key)] = std::string(OptionChoices<T>::Name(value));
    } else {
      json[std::string(field.key)] = value;
    }
  });
  return json;
}

DetectorOptions DetectorOptionsFromJson(const nlohmann::json& json, std::string_view what,
                                        DetectorOptions base) {
  if (!json.is_object()) throw FormatError(std::string(what) + " is not a JSON object");
  std::set<std::string> known;
  VisitDetectorOptions(base, [&](const DetectorOptionField& field, auto& value) {
    known.insert(std::string(field.key));
    const auto it = json.find(field.key);
    if (it == json.end()) return;
    using T = std::decay_t<decltype(value)>;
    if constexpr (kIsChoiceOption<T>) {
      ReadChoice(*it, field, what, value);
    } else {
      ReadNumber(*it, field, what, value);
    }
  });
  for (const auto& [key, value] : json.items()) {
    if (!known.contains(key)) {
      throw FormatError(std::string(what) + ": unknown detector setting '" + key + "'");
    }
  }
  try {
    base.Validate();
  } catch (const Error& error) {
    throw FormatError(std::string(what) + ": " + error.what());
  }
  return base;
}

DetectorOptions ReadDetectorProfile(const std::filesystem::path& path, DetectorOptions base) {
  const std::string text = ReadFileBytes(path);
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw FormatError(Quoted(path) + ": not valid JSON");
  const bool wrapped = json.is_object() && json.contains("detector");
  return DetectorOptionsFromJson(wrapped ? json["detector"] : json, Quoted(path), base);
}

void WriteDetectorProfile(const std::filesystem::path& path, const DetectorOptions& options) {
  options.Validate();
  const nlohmann::json json = {{"detector", DetectorOptionsToJson(options)}};
  WriteFileAtomically(path, json.dump(2) + "\n");
}

}  // namespace layermod
