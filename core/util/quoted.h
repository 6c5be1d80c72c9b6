// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace layermod {

// 'text' in single quotes: how file names and keys appear in every error message.
std::string Quoted(std::string_view text);
std::string Quoted(const std::filesystem::path& path);
inline std::string Quoted(const std::string& text) { return Quoted(std::string_view(text)); }
inline std::string Quoted(const char* text) { return Quoted(std::string_view(text)); }

}  // namespace layermod
