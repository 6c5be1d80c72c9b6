// SPDX-License-Identifier: MIT
#pragma once

// Typed access to the fields of a JSON object for the manifest and profile readers: every
// failure is a FormatError naming the field's full path ("objects[0].sphere.radius_mm").

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "util/error.h"

namespace layermod {

class JsonFields {
 public:
  // `what` names the document ("manifest"), `path` the object inside it ("" for the root).
  JsonFields(const nlohmann::json& object, std::string what, std::string path)
      : object_(object), what_(std::move(what)), path_(std::move(path)) {
    if (!object_.is_object()) {
      throw FormatError(what_ + (path_.empty() ? " is not a JSON object"
                                               : " field '" + path_ + "' is not a JSON object"));
    }
  }

  bool Has(std::string_view key) const { return object_.contains(key); }

  std::string PathOf(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }

  [[noreturn]] void Fail(std::string_view key, std::string_view problem) const {
    throw FormatError(what_ + " field '" + PathOf(key) + "' " + std::string(problem));
  }

  const nlohmann::json& Get(std::string_view key) const {
    const auto it = object_.find(key);
    if (it == object_.end()) Fail(key, "is missing");
    return *it;
  }

  JsonFields Object(std::string_view key) const { return {Get(key), what_, PathOf(key)}; }

  double Number(std::string_view key) const {
    const nlohmann::json& value = Get(key);
    if (!value.is_number()) Fail(key, "must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) Fail(key, "must be finite");
    return number;
  }

  std::int64_t Integer(std::string_view key, std::int64_t min, std::int64_t max) const {
    const nlohmann::json& value = Get(key);
    if (!value.is_number_integer()) Fail(key, "must be an integer");
    const bool too_big =
        value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(max);
    const std::int64_t number = too_big ? max : value.get<std::int64_t>();
    if (too_big || number < min || number > max) {
      Fail(key, "must be within " + std::to_string(min) + ".." + std::to_string(max));
    }
    return number;
  }

  std::uint64_t Unsigned(std::string_view key) const {
    const nlohmann::json& value = Get(key);
    if (!value.is_number_unsigned()) Fail(key, "must be a non-negative integer");
    return value.get<std::uint64_t>();
  }

  std::string String(std::string_view key) const {
    const nlohmann::json& value = Get(key);
    if (!value.is_string()) Fail(key, "must be a string");
    return value.get<std::string>();
  }

  const nlohmann::json& Array(std::string_view key) const {
    const nlohmann::json& value = Get(key);
    if (!value.is_array()) Fail(key, "must be an array");
    return value;
  }

  // Unknown keys are refused so a misspelt field is not silently ignored.
  void RejectUnknown(std::initializer_list<std::string_view> known) const {
    for (const auto& [key, value] : object_.items()) {
      bool found = false;
      for (std::string_view name : known) found = found || key == name;
      if (!found) Fail(key, "is not a known field");
    }
  }

 private:
  const nlohmann::json& object_;
  std::string what_;
  std::string path_;
};

}  // namespace layermod
