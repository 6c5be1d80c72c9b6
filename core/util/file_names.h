// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>

namespace layermod {

// The file name's extension with its dot, in lower case (".PLY" -> ".ply"); empty when none.
std::string LowercaseExtension(const std::filesystem::path& path);

}  // namespace layermod
