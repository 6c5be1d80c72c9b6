// SPDX-License-Identifier: MIT
#include "util/version.h"

namespace layermod {

std::string ToolVersion() { return LAYERMOD_VERSION; }

}  // namespace layermod
