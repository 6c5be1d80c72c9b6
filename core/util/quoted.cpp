// SPDX-License-Identifier: MIT
#include "util/quoted.h"

namespace layermod {

std::string Quoted(std::string_view text) {
  // Appended piecewise: GCC 12 raises a false -Wrestrict on "'" + string + "'" at -O3.
  std::string quoted(1, '\'');
  quoted += text;
  quoted += '\'';
  return quoted;
}

std::string Quoted(const std::filesystem::path& path) {
  return Quoted(std::string_view(path.string()));
}

}  // namespace layermod
