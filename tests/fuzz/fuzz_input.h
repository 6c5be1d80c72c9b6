// SPDX-License-Identifier: MIT
#pragma once
// Helpers shared by the fuzz targets: the loaders under test read files, so each input is
// written to a scratch directory first (in memory under /dev/shm when it exists).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace layermod::fuzz {

// Separates the files of a multi-file input (a capture: camera JSON, depth PNG, colour PNG).
// Text that cannot occur by chance in a seed, short enough for the mutator to keep or make.
inline constexpr std::string_view kPartSeparator = "\n--LMFZ--\n";

// Splits `bytes` on kPartSeparator into exactly `count` parts (missing ones are empty, extra
// separators stay inside the last part).
std::vector<std::string_view> SplitParts(std::string_view bytes, std::size_t count);

// Joins files into one input, the inverse of SplitParts (for making seeds).
std::string JoinParts(const std::vector<std::string>& parts);

// Call first in every target: drops the core's log messages (warnings about fuzzed meshes would
// otherwise flood the output and slow the run) once per process.
void QuietLogsOnce();

// A per-process scratch directory, emptied before each input.
const std::filesystem::path& ScratchDir();
void ClearScratchDir();

// Writes `bytes` to ScratchDir()/name and returns the path.
std::filesystem::path WriteScratchFile(const std::string& name, std::string_view bytes);

// The fuzzing contract for a refused input: its message must name the file (`name` is a path or
// a file name that the message must contain); aborts (a finding) otherwise.
void AbortUnlessNamed(const std::exception& error, const std::string& name);

// Runs `load`; a layermod::Error it throws must name `name` (AbortUnlessNamed).
template <typename F>
void LoadOrNameTheFile(F&& load, const std::string& name) {
  try {
    load();
  } catch (const Error& error) {
    AbortUnlessNamed(error, name);
  }
}

inline std::string_view AsText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace layermod::fuzz
