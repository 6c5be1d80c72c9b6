// SPDX-License-Identifier: MIT
#include "geometry/units.h"

#include "util/error.h"

namespace layermod {

LengthUnit ParseLengthUnit(std::string_view text) {
  if (text == "mm") return LengthUnit::kMillimetre;
  if (text == "m") return LengthUnit::kMetre;
  throw Error("units: expected 'mm' or 'm', got '" + std::string(text) + "'");
}

}  // namespace layermod
