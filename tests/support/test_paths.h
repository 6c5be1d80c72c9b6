// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>

namespace layermod::test {

// The repository root (for resources/).
std::filesystem::path SourceDir();

// ../shared/data beside the repository, or $LAYERMOD_DATA_DIR; nullopt when absent (tests that
// need it then GTEST_SKIP with a message).
std::optional<std::filesystem::path> SharedDataDir();

// A fresh empty directory under the system temp dir, removed when the returned object dies.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

}  // namespace layermod::test
