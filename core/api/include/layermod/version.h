// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace layermod::api {

// The library's version, e.g. "0.1.0". Stable between versions: the <layermod/...> headers and
// the archive format (below); everything else in the core may change.
std::string Version();

// The *.layermod format version this library reads and writes.
int ArchiveFormatVersion();

}  // namespace layermod::api
