// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace layermod {

enum class LengthUnit { kMillimetre, kMetre };

inline double MillimetresPer(LengthUnit unit) { return unit == LengthUnit::kMetre ? 1000.0 : 1.0; }
inline std::string UnitName(LengthUnit unit) { return unit == LengthUnit::kMetre ? "m" : "mm"; }
// Parses "mm" or "m"; throws Error otherwise.
LengthUnit ParseLengthUnit(std::string_view text);

}  // namespace layermod
