// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace layermod {

// Writes `bytes` to `path` atomically: a temporary file in the same directory, flushed and
// fsync'ed, then renamed over `path`. On any failure the temporary file is removed and `path`
// keeps its previous content (or stays absent). Throws IoError naming `path`.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Reads a whole file. Throws IoError naming `path` when it cannot be opened or read.
std::string ReadFileBytes(const std::filesystem::path& path);

// Throws IoError when `path` cannot be created/replaced (missing or unwritable directory).
// Lets long jobs fail before the work rather than after it.
void CheckWritableTarget(const std::filesystem::path& path);

}  // namespace layermod
