// SPDX-License-Identifier: MIT
// Models folders and options for the generator's tests: small images, few models.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "support/test_cameras.h"
#include "synth/synth_options.h"

namespace layermod::test {

// `dir`/models/obj_000001.ply: the bundled sample bracket (always available).
std::filesystem::path WriteBracketModels(const std::filesystem::path& dir);

// `dir`/lmo-models/ linking the LineMOD models `obj_ids` and models_info.json of the shared
// data; nullopt when the shared data is absent.
std::optional<std::filesystem::path> LinkLmoModels(const std::filesystem::path& dir,
                                                   const std::vector<int>& obj_ids);

// Options for `scenes` small images of `obj_ids` from `models_dir` into `out_dir`.
SynthOptions SmallOptions(const std::filesystem::path& models_dir,
                          const std::vector<std::int32_t>& obj_ids, int scenes,
                          const std::filesystem::path& out_dir);

}  // namespace layermod::test
