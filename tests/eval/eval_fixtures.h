// SPDX-License-Identifier: MIT
// A tiny synthetic BOP dataset of the bundled bracket and a small archive trained for it.
#pragma once

#include <filesystem>

#include "templates/archive.h"

namespace layermod::test {

struct TinyEvalData {
  std::filesystem::path dataset;  // BOP root: test/000001/, models/, test_targets_bop19.json
  std::filesystem::path archive_file;
  TemplateArchive archive;  // object 1, the dataset's 320 x 240 camera
};

// A few dozen views of the bracket (obj 1, the synthetic camera) at the layers of dmin..dmax.
TemplateArchive TrainBracketArchive(double dmin_mm, double dmax_mm);

// `images` seeded synthetic images of object 1 (bracket) in `dir`/data and an archive of a few
// dozen templates over 600..1200 mm in `dir`/bracket.layermod.
TinyEvalData MakeTinyEvalData(const std::filesystem::path& dir, int images);

}  // namespace layermod::test
