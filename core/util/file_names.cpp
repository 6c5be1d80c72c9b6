// SPDX-License-Identifier: MIT
#include "util/file_names.h"

#include <algorithm>
#include <cctype>

namespace layermod {

std::string LowercaseExtension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace layermod
