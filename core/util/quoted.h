// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace layermod {

// 'text' in single quotes: how file names and keys appear in every error message.
std::string Quoted(std::string_view text);
std::string Quoted(const std::filesystem::path& path);

}  // namespace layermod
