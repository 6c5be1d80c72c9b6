// SPDX-License-Identifier: MIT
#include <layermod/version.h>

#include "templates/archive.h"
#include "util/version.h"

namespace layermod::api {

std::string Version() { return ToolVersion(); }

int ArchiveFormatVersion() { return kArchiveFormatVersion; }

}  // namespace layermod::api
