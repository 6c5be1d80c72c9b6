// SPDX-License-Identifier: MIT
// Fuzz target: the *.layermod reader. Any input must load or fail with a layermod::Error that
// names the file; anything else (crash, other exception, sanitizer report) is a finding.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_input.h"
#include "templates/archive.h"
#include "util/error.h"

namespace {

// The per-layer index of a loaded archive must partition each object's templates.
void CheckIndex(const layermod::TemplateArchive& archive) {
  for (const layermod::ArchiveObject& object : archive.manifest().objects) {
    std::size_t in_layers = 0;
    for (std::size_t layer = 0; layer < object.layer_depths_mm.size(); ++layer) {
      in_layers += archive.TemplatesOf(object.obj_id, static_cast<int>(layer)).size();
    }
    if (in_layers != archive.TemplatesOf(object.obj_id).size()) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace layermod;
  fuzz::QuietLogsOnce();
  const std::string name = "fuzz-input.layermod";
  fuzz::LoadOrNameTheFile([&] { CheckIndex(ReadArchiveBytes(fuzz::AsText(data, size), name)); },
                          name);
  return 0;
}
