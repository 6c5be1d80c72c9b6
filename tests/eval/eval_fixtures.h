// SPDX-License-Identifier: MIT
// A tiny synthetic BOP dataset of the bundled bracket and a small archive trained for it.
#pragma once

#include <filesystem>

#include <gtest/gtest.h>

#include "pipeline/detector.h"
#include "support/test_paths.h"
#include "templates/archive.h"

namespace layermod::test {

struct TinyEvalData {
  std::filesystem::path dataset;  // BOP root: test/000001/, models/, test_targets_bop19.json
  std::filesystem::path archive_file;
  TemplateArchive archive;  // object 1, the dataset's 320 x 240 camera
};

// The bracket rendered at the pose of one of its templates in front of a grey wall 150 mm
// behind it: that template matches it exactly, so a detector must find it.
Capture CaptureAtTemplatePose(const TemplateArchive& archive, const TemplateRecord& record);

// A few dozen views of the bracket (obj 1, the synthetic camera) at the layers of dmin..dmax.
TemplateArchive TrainBracketArchive(double dmin_mm, double dmax_mm);

// `images` seeded synthetic images of object 1 (bracket) in `dir`/data and an archive of a few
// dozen templates over 600..1200 mm in `dir`/bracket.layermod.
TinyEvalData MakeTinyEvalData(const std::filesystem::path& dir, int images);

// A test suite sharing one tiny dataset of `kImages` images, made once for the whole suite.
template <int kImages>
class TinyEvalSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    data_ = new TinyEvalData(MakeTinyEvalData(dir_->path(), kImages));
  }
  static void TearDownTestSuite() {
    delete data_;
    delete dir_;
    data_ = nullptr;
    dir_ = nullptr;
  }

  static inline TempDir* dir_ = nullptr;
  static inline TinyEvalData* data_ = nullptr;
};

}  // namespace layermod::test
