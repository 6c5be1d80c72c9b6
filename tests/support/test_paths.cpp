// SPDX-License-Identifier: MIT
#include "support/test_paths.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace layermod::test {
namespace fs = std::filesystem;

fs::path SourceDir() { return LAYERMOD_SOURCE_DIR; }

std::optional<fs::path> SharedDataDir() {
  if (const char* env = std::getenv("LAYERMOD_DATA_DIR"); env != nullptr && *env != '\0') {
    if (fs::is_directory(env)) return fs::path(env);
    return std::nullopt;
  }
  const fs::path beside = LAYERMOD_SHARED_DATA_DIR;
  if (fs::is_directory(beside / "lmo-dev")) return beside;
  return std::nullopt;
}

TempDir::TempDir() {
  std::string pattern = (fs::temp_directory_path() / "layermod-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

}  // namespace layermod::test
