// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace layermod {

std::string ToolVersion();  // e.g. "0.1.0"

}  // namespace layermod
