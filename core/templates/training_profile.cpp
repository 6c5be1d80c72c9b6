// SPDX-License-Identifier: MIT
#include "templates/training_profile.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "geometry/up_axis.h"
#include "templates/json_fields.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/quoted.h"

namespace layermod {
namespace {

constexpr const char* kWhat = "training profile";

// Shortest text that reads back to the same value, so files stay readable ("0.3", not
// "0.30000001192092896") and still round-trip exactly.
template <typename T>
std::string ShortestText(T value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

double FloatForJson(float value) {
  const std::string text = ShortestText(value);
  double number = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), number);
  return number;
}

std::string RangeText(const AngleRange& range) {
  return ShortestText(range.min_deg) + ":" + ShortestText(range.step_deg) + ":" +
         ShortestText(range.max_deg);
}

// "min:step:max" or {"min_deg", "step_deg", "max_deg"}.
AngleRange ReadRange(const JsonFields& fields, std::string_view key) {
  const nlohmann::json& value = fields.Get(key);
  if (value.is_object()) {
    const JsonFields range_fields = fields.Object(key);
    range_fields.RejectUnknown({"min_deg", "step_deg", "max_deg"});
    AngleRange range{range_fields.Number("min_deg"), range_fields.Number("step_deg"),
                     range_fields.Number("max_deg")};
    try {
      range.Validate(fields.PathOf(key));
    } catch (const Error& error) {
      fields.Fail(key, std::string("is invalid: ") + error.what());
    }
    return range;
  }
  if (!value.is_string()) fields.Fail(key, "must be a \"min:step:max\" string");
  try {
    return AngleRange::Parse(value.get<std::string>(), fields.PathOf(key));
  } catch (const Error& error) {
    fields.Fail(key, std::string("is invalid: ") + error.what());
  }
}

float ReadFloat(const JsonFields& fields, std::string_view key) {
  const double number = fields.Number(key);
  if (std::abs(number) > std::numeric_limits<float>::max()) fields.Fail(key, "is out of range");
  return static_cast<float>(number);
}

int ReadInt(const JsonFields& fields, std::string_view key) {
  return static_cast<int>(
      fields.Integer(key, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

// The reference orientation: "up_axis" when it is one of the six axes, else the rotation.
std::pair<std::string, nlohmann::json> UprightJson(const Eigen::Matrix3d& upright_from_model) {
  if (const std::optional<std::string> axis = UpAxisName(upright_from_model)) {
    return {"up_axis", *axis};
  }
  nlohmann::json rows = nlohmann::json::array();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) rows.push_back(upright_from_model(row, col));
  }
  return {"upright_from_model", rows};
}

Eigen::Matrix3d ReadUpright(const JsonFields& fields) {
  if (fields.Has("up_axis") && fields.Has("upright_from_model")) {
    fields.Fail("up_axis", "and 'upright_from_model' cannot both be given");
  }
  if (fields.Has("up_axis")) {
    const nlohmann::json& axis = fields.Get("up_axis");
    if (!axis.is_string()) fields.Fail("up_axis", "must be one of +x, -x, +y, -y, +z, -z");
    try {
      return UprightFromUpAxis(axis.get<std::string>());
    } catch (const Error&) {
      fields.Fail("up_axis", "must be one of +x, -x, +y, -y, +z, -z");
    }
  }
  if (!fields.Has("upright_from_model")) return Eigen::Matrix3d::Identity();
  const nlohmann::json& values = fields.Array("upright_from_model");
  if (values.size() != 9) fields.Fail("upright_from_model", "must hold 9 numbers (row-major)");
  Eigen::Matrix3d rotation;
  for (int i = 0; i < 9; ++i) {
    if (!values[static_cast<std::size_t>(i)].is_number()) {
      fields.Fail("upright_from_model", "must hold 9 numbers (row-major)");
    }
    rotation(i / 3, i % 3) = values[static_cast<std::size_t>(i)].get<double>();
  }
  try {
    ValidateRotation(rotation, "upright_from_model");
  } catch (const Error&) {
    fields.Fail("upright_from_model", "is not a rotation (orthonormal rows, determinant +1)");
  }
  return rotation;
}

ViewSamplingOptions ReadViews(const JsonFields& fields) {
  fields.RejectUnknown(
      {"azimuth", "elevation", "roll", "even_spacing_deg", "up_axis", "upright_from_model"});
  ViewSamplingOptions views = TrainingProfile::DefaultEnvelopeViews();
  if (fields.Has("azimuth")) views.azimuth = ReadRange(fields, "azimuth");
  if (fields.Has("elevation")) views.elevation = ReadRange(fields, "elevation");
  if (fields.Has("roll")) views.roll = ReadRange(fields, "roll");
  if (fields.Has("even_spacing_deg")) views.even_spacing_deg = fields.Number("even_spacing_deg");
  views.upright_from_model = ReadUpright(fields);
  return views;
}

std::vector<int> ReadSpread(const JsonFields& fields) {
  std::vector<int> spread_px;
  for (const nlohmann::json& value : fields.Array("spread_px")) {
    if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
        value.get<std::int64_t>() > 1000) {
      fields.Fail("spread_px", "must be an array of small non-negative integers");
    }
    spread_px.push_back(value.get<int>());
  }
  return spread_px;
}

FeatureOptions ReadFeatures(const JsonFields& fields) {
  fields.RejectUnknown({"color_features", "normal_features", "min_features", "weak_gradient",
                        "strong_gradient", "max_normal_depth_step_mm", "pyramid_levels",
                        "spread_px", "depth_edge_fraction", "normal_frame"});
  FeatureOptions options;
  if (fields.Has("color_features")) options.color_features = ReadInt(fields, "color_features");
  if (fields.Has("normal_features")) options.normal_features = ReadInt(fields, "normal_features");
  if (fields.Has("min_features")) options.min_features = ReadInt(fields, "min_features");
  if (fields.Has("weak_gradient")) options.weak_gradient = ReadFloat(fields, "weak_gradient");
  if (fields.Has("strong_gradient")) options.strong_gradient = ReadFloat(fields, "strong_gradient");
  if (fields.Has("max_normal_depth_step_mm")) {
    options.max_normal_depth_step_mm = ReadFloat(fields, "max_normal_depth_step_mm");
  }
  if (fields.Has("pyramid_levels")) options.pyramid_levels = ReadInt(fields, "pyramid_levels");
  if (fields.Has("spread_px")) options.spread_px = ReadSpread(fields);
  if (fields.Has("depth_edge_fraction")) {
    options.depth_edge_fraction = ReadFloat(fields, "depth_edge_fraction");
  }
  if (fields.Has("normal_frame")) {
    const std::optional<NormalFrame> frame = NormalFrameFromName(fields.String("normal_frame"));
    if (!frame) fields.Fail("normal_frame", "must be \"camera\" or \"viewing_ray\"");
    options.normal_frame = *frame;
  }
  return options;
}

}  // namespace

const std::vector<std::string>& ViewPresetNames() {
  static const std::vector<std::string> names = {"tabletop", "full"};
  return names;
}

ViewSamplingOptions ViewPreset(std::string_view name, const Eigen::Matrix3d& upright_from_model) {
  ViewSamplingOptions views = TrainingProfile::DefaultEnvelopeViews();
  if (name == "full") {
    views.elevation = {-90.0, 15.0, 90.0};
    views.roll = {-180.0, 15.0, 165.0};
  } else if (name != "tabletop") {
    throw Error("view preset: '" + std::string(name) + "' is not tabletop or full");
  }
  views.upright_from_model = upright_from_model;
  return views;
}

ViewSamplingOptions TrainingProfile::DefaultEnvelopeViews() {
  ViewSamplingOptions views;
  // The grid values only matter when a user switches even sampling off.
  views.azimuth = {0.0, 15.0, 345.0};
  views.elevation = {0.0, 15.0, 90.0};
  views.roll = {-45.0, 15.0, 45.0};
  views.even_spacing_deg = 12.0;
  return views;
}

void TrainingProfile::Validate() const {
  if (!std::isfinite(depth_min_mm) || !std::isfinite(depth_max_mm)) {
    throw Error("depth range: depth_min_mm and depth_max_mm must be finite");
  }
  if (depth_min_mm <= 0.0) throw Error("depth range: depth_min_mm must be positive");
  if (depth_min_mm >= depth_max_mm) {
    throw Error("depth range: D_min must be below D_max (depth_min_mm must be below depth_max_mm)");
  }
  views.Validate();
  features.Validate();
}

nlohmann::json ToJson(const TrainingProfile& profile) {
  const FeatureOptions& features = profile.features;
  return {
      {"depth_min_mm", profile.depth_min_mm},
      {"depth_max_mm", profile.depth_max_mm},
      {"views",
       {{"azimuth", RangeText(profile.views.azimuth)},
        {"elevation", RangeText(profile.views.elevation)},
        {"roll", RangeText(profile.views.roll)},
        {"even_spacing_deg", profile.views.even_spacing_deg},
        UprightJson(profile.views.upright_from_model)}},
      {"features",
       {{"color_features", features.color_features},
        {"normal_features", features.normal_features},
        {"min_features", features.min_features},
        {"weak_gradient", FloatForJson(features.weak_gradient)},
        {"strong_gradient", FloatForJson(features.strong_gradient)},
        {"max_normal_depth_step_mm", FloatForJson(features.max_normal_depth_step_mm)},
        {"pyramid_levels", features.pyramid_levels},
        {"spread_px", features.spread_px},
        {"depth_edge_fraction", FloatForJson(features.depth_edge_fraction)},
        {"normal_frame", NormalFrameName(features.normal_frame)}}},
  };
}

// Missing fields keep their defaults, so a profile file may hold only what it changes.
TrainingProfile TrainingProfileFromJson(const nlohmann::json& json) {
  const JsonFields fields(json, kWhat, "");
  fields.RejectUnknown({"depth_min_mm", "depth_max_mm", "views", "features"});
  TrainingProfile profile;
  if (fields.Has("depth_min_mm")) profile.depth_min_mm = fields.Number("depth_min_mm");
  if (fields.Has("depth_max_mm")) profile.depth_max_mm = fields.Number("depth_max_mm");
  if (fields.Has("views")) profile.views = ReadViews(fields.Object("views"));
  if (fields.Has("features")) profile.features = ReadFeatures(fields.Object("features"));
  try {
    profile.Validate();
  } catch (const Error& error) {
    throw FormatError(std::string(kWhat) + ": " + error.what());
  }
  return profile;
}

void SaveTrainingProfile(const std::filesystem::path& path, const TrainingProfile& profile) {
  try {
    profile.Validate();
  } catch (const Error& error) {
    throw Error(Quoted(path) + ": not saved: " + error.what());
  }
  WriteFileAtomically(path, ToJson(profile).dump(2) + "\n");
}

TrainingProfile LoadTrainingProfile(const std::filesystem::path& path) {
  const std::string text = ReadFileBytes(path);
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded()) throw FormatError(Quoted(path) + ": not valid JSON");
  try {
    return TrainingProfileFromJson(json);
  } catch (const FormatError& error) {
    throw FormatError(Quoted(path) + ": " + error.what());
  }
}

}  // namespace layermod
