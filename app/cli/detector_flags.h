// SPDX-License-Identifier: MIT
// The detector settings of `layermod detect`, `eval` and `bench`: one flag per field of the
// detector options table (pipeline/detector_options.h) plus --detector-profile FILE. The profile
// is read first; flags given on the command line override its fields.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "pipeline/detector.h"

namespace layermod::cli {

class DetectorFlags {
 public:
  enum class Kind { kInteger, kReal, kText };  // how a flag's text becomes its field's value

  // Adds every flag to `command`, with the defaults of `defaults` in the help.
  void AddTo(CLI::App* command, const DetectorOptions& defaults = {});

  // The options after parsing: defaults, then the profile, then the flags given. Throws
  // CLI::ValidationError naming the flag for values out of range, Error/FormatError for an
  // unreadable profile or inconsistent settings.
  DetectorOptions Resolve() const;

 private:
  struct Flag {
    CLI::Option* option = nullptr;
    std::string key;
    Kind kind = Kind::kText;
  };
  DetectorOptions defaults_;
  std::vector<Flag> flags_;
  std::string profile_path_;
};

}  // namespace layermod::cli
