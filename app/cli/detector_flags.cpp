// SPDX-License-Identifier: MIT
#include "cli/detector_flags.h"

#include <charconv>
#include <optional>
#include <type_traits>

#include "pipeline/detector_options.h"
#include "util/error.h"

namespace layermod::cli {
namespace {

// A flag's text as a number of its field's kind; nullopt when it is not one.
std::optional<nlohmann::json> ParseNumber(const std::string& text, DetectorFlags::Kind kind) {
  try {
    std::size_t used = 0;
    const nlohmann::json number = kind == DetectorFlags::Kind::kInteger
                                      ? nlohmann::json(std::stoll(text, &used))
                                      : nlohmann::json(std::stod(text, &used));
    if (used == text.size()) return number;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// Checks a flag's text: a number (an integer for integer fields) within the field's range.
CLI::Validator RangeCheck(const DetectorOptionField& field, DetectorFlags::Kind kind) {
  const std::string range = "in [" + FormatRange(field.min) + ", " + FormatRange(field.max) + "]";
  return CLI::Validator(
      [field, kind, range](std::string& text) -> std::string {
        const std::optional<nlohmann::json> number = ParseNumber(text, kind);
        if (!number) {
          return "'" + text + "' is not " +
                 (kind == DetectorFlags::Kind::kInteger ? "an integer" : "a number");
        }
        const double value = number->get<double>();
        if (!(value >= field.min && value <= field.max)) return "'" + text + "' is not " + range;
        return "";
      },
      range);
}

// A default as the help shows it: floats by their shortest text ("0.8", not 0.800000011...).
template <typename T>
std::string DefaultText(const T& value) {
  if constexpr (kIsChoiceOption<T>) {
    return std::string(OptionChoices<T>::Name(value));
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
    Kind kind = Kind::kText;
    if constexpr (kIsChoiceOption<T>) {
      option->type_name("NAME")->check(CLI::IsMember(ChoiceNames<T>()));
    } else {
      kind = std::is_integral_v<T> ? Kind::kInteger : Kind::kReal;
      option->type_name(kind == Kind::kInteger ? "INT" : "NUMBER")->check(RangeCheck(field, kind));
    }
    flags_.push_back({option, std::string(field.key), kind});
  });
}

DetectorOptions DetectorFlags::Resolve() const {
  const DetectorOptions base =
      profile_path_.empty() ? defaults_ : ReadDetectorProfile(profile_path_, defaults_);
  nlohmann::json given = nlohmann::json::object();
  for (const Flag& flag : flags_) {
    if (flag.option->count() == 0) continue;
    // The option's validator has checked the text already.
    const std::string text = flag.option->as<std::string>();
    given[flag.key] =
        flag.kind == Kind::kText ? nlohmann::json(text) : *ParseNumber(text, flag.kind);
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
