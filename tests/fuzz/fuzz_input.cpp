// SPDX-License-Identifier: MIT
#include "fuzz/fuzz_input.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "util/log.h"

namespace layermod::fuzz {
namespace fs = std::filesystem;

std::vector<std::string_view> SplitParts(std::string_view bytes, std::size_t count) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < count) {
    const std::size_t at = bytes.find(kPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(bytes.substr(0, at));
    bytes.remove_prefix(at + kPartSeparator.size());
  }
  parts.push_back(bytes);
  parts.resize(count);
  return parts;
}

std::string JoinParts(const std::vector<std::string>& parts) {
  std::string joined;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) joined += kPartSeparator;
    joined += parts[i];
  }
  return joined;
}

void QuietLogsOnce() {
  static const bool quiet = [] {
    SetLogSink([](LogLevel, std::string_view) {});
    return true;
  }();
  (void)quiet;
}

const fs::path& ScratchDir() {
  static const fs::path dir = [] {
    const fs::path base =
        fs::is_directory("/dev/shm") ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path path = base / ("layermod-fuzz-" + std::to_string(getpid()));
    fs::create_directories(path);
    return path;
  }();
  return dir;
}

void ClearScratchDir() {
  for (const auto& entry : fs::directory_iterator(ScratchDir())) fs::remove_all(entry.path());
}

void AbortUnlessNamed(const std::exception& error, const std::string& name) {
  if (std::string(error.what()).find(name) != std::string::npos) return;
  std::fprintf(stderr, "error message does not name the file: %s\n", error.what());
  std::abort();
}

fs::path WriteScratchFile(const std::string& name, std::string_view bytes) {
  const fs::path path = ScratchDir() / name;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("fuzz harness: cannot write " + path.string());
  return path;
}

}  // namespace layermod::fuzz
