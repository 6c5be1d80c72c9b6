// SPDX-License-Identifier: MIT
#include "cli/detector_flags.h"

#include <charconv>
#include <type_traits>

#include "pipeline/detector_options.h"
#include "util/error.h"

namespace layermod::cli {
namespace {

// The value a flag was given, as the JSON value of its field.
nlohmann::json GivenValue(const CLI::Option& option, const std::string& flag, bool integer,
                          bool text) {
  const std::string value = option.as<std::string>();
  if (text) return value;
  try {
    std::size_t used = 0;
    const nlohmann::json number = integer ? nlohmann::json(std::stoll(value, &used))
                                          : nlohmann::json(std::stod(value, &used));
    if (used == value.size()) return number;
  } catch (const std::exception&) {
  }
  throw CLI::ValidationError(flag,
                             "'" + value + "' is not " + (integer ? "an integer" : "a number"));
}

// Checks a flag's text: a number (an integer for integer fields) within the field's range.
CLI::Validator RangeCheck(const DetectorOptionField& field, bool integer) {
  const std::string range = "in [" + FormatRange(field.min) + ", " + FormatRange(field.max) + "]";
  return CLI::Validator(
      [field, integer, range](std::string& text) -> std::string {
        std::size_t used = 0;
        double value = 0.0;
        try {
          value = integer ? static_cast<double>(std::stoll(text, &used)) : std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size()) {
          return "'" + text + "' is not " + (integer ? "an integer" : "a number");
        }
        if (!(value >= field.min && value <= field.max)) return "'" + text + "' is not " + range;
        return "";
      },
      range);
}

// A default as the help shows it: floats by their shortest text ("0.8", not 0.800000011...).
template <typename T>
std::string DefaultText(const T& value) {
  if constexpr (std::is_same_v<T, DetectionMode>) {
    return std::string(ModeName(value));
  } else {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, value).ptr;
    return std::string(text, end);
  }
}

}  // namespace

void DetectorFlags::AddTo(CLI::App* command, const DetectorOptions& defaults) {
  defaults_ = defaults;
  command->add_option("--detector-profile", profile_path_,
                      "Detector settings (JSON) to start from; flags override its fields");
  DetectorOptions scratch = defaults;
  VisitDetectorOptions(scratch, [&](const DetectorOptionField& field, auto& value) {
    using T = std::decay_t<decltype(value)>;
    CLI::Option* option =
        command->add_option(OptionFlag(field))->description(std::string(field.help));
    option->default_str(DefaultText(value));
    if constexpr (std::is_same_v<T, DetectionMode>) {
      option->type_name("MODE")->check(CLI::IsMember({"scene-patch", "exhaustive", "color-only"}));
    } else {
      option->type_name(std::is_integral_v<T> ? "INT" : "NUMBER")
          ->check(RangeCheck(field, std::is_integral_v<T>));
    }
    flags_.push_back({option, std::string(field.key)});
  });
}

DetectorOptions DetectorFlags::Resolve() const {
  const DetectorOptions base =
      profile_path_.empty() ? defaults_ : ReadDetectorProfile(profile_path_, defaults_);
  const nlohmann::json kinds = DetectorOptionsToJson(base);
  nlohmann::json given = nlohmann::json::object();
  for (const Flag& flag : flags_) {
    if (flag.option->count() == 0) continue;
    const nlohmann::json& kind = kinds.at(flag.key);
    given[flag.key] = GivenValue(*flag.option, flag.option->get_name(), kind.is_number_integer(),
                                 kind.is_string());
  }
  try {
    return DetectorOptionsFromJson(given, "command line", base);
  } catch (const FormatError& error) {
    // Settings that contradict each other (--edge-upper below --edge-lower ...): a usage error.
    std::string flags;
    for (const auto& [key, value] : given.items()) {
      flags += (flags.empty() ? "" : ", ") + OptionFlag(DetectorOptionField{key, "", "", 0, 0});
    }
    throw CLI::ValidationError(flags.empty() ? "--detector-profile" : flags, error.what());
  }
}

}  // namespace layermod::cli
