// SPDX-License-Identifier: MIT
#include "synth/model_library.h"
#include "support/thrown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "support/test_paths.h"
#include "synth_fixtures.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using test::ThrownMessage;

TEST(ModelLibraryTest, ListsBopModelFilesById) {
  test::TempDir dir;
  const fs::path models = test::WriteBracketModels(dir.path());
  std::ofstream(models / "obj_000012.ply") << "x";
  std::ofstream(models / "notes.txt") << "x";
  std::ofstream(models / "obj_12.stl") << "x";
  const auto files = ListModelFiles(models);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files.at(1).filename(), "obj_000001.ply");
  EXPECT_EQ(files.at(12).filename(), "obj_000012.ply");
}

TEST(ModelLibraryTest, FolderProblemsAreIoErrors) {
  test::TempDir dir;
  EXPECT_THAT(ThrownMessage<IoError>([&] { ListModelFiles(dir / "missing"); }),
              HasSubstr("models folder does not exist"));
  EXPECT_THAT(ThrownMessage<IoError>([&] { ListModelFiles(dir.path()); }),
              HasSubstr("no model files"));
}

TEST(ModelLibraryTest, ASinglePlyFileIsOneObject) {
  test::TempDir dir;
  const fs::path models = test::WriteBracketModels(dir.path());
  const fs::path file = models / "obj_000001.ply";
  const auto files = ModelFilesFor(file, {4, 4});
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files.at(4), file);
  EXPECT_EQ(ModelFilesFor(models, {1}).size(), 1u);  // a folder: its BOP files
  EXPECT_THAT(ThrownMessage<Error>([&] {
                ModelFilesFor(file, {1, 2});
              }),
              HasSubstr("give one object id"));
  std::ofstream(dir / "part.stl") << "solid x";
  EXPECT_THAT(ThrownMessage<Error>([&] { ModelFilesFor(dir / "part.stl", {1}); }),
              HasSubstr("must be a PLY file"));
}

TEST(ModelLibraryTest, LoadsMeshSphereAndComputedInfo) {
  test::TempDir dir;
  const fs::path models = test::WriteBracketModels(dir.path());
  const auto loaded = LoadSynthModels(models, ListModelFiles(models), {1});
  const SynthModel& bracket = loaded.at(1);
  EXPECT_EQ(bracket.obj_id, 1);
  EXPECT_FALSE(bracket.mesh.triangles.empty());
  EXPECT_GT(bracket.sphere.radius_mm, 50.0);
  // No models_info.json: computed. The diameter is at most the sphere's and at least the
  // bounding box's largest side.
  EXPECT_LE(bracket.info.diameter_mm, 2.0 * bracket.sphere.radius_mm + 1e-9);
  EXPECT_GE(bracket.info.diameter_mm, bracket.info.size.maxCoeff());
  EXPECT_NEAR(bracket.info.size.x(), 100.0, 1e-3);
  EXPECT_FALSE(bracket.info.IsSymmetric());
  EXPECT_THAT(ThrownMessage<Error>([&] { LoadSynthModels(models, ListModelFiles(models), {3}); }),
              HasSubstr("object 3 has no model"));
}

TEST(ModelLibraryTest, TakesInfoAndSymmetriesFromModelsInfoJson) {
  test::TempDir dir;
  const auto models = test::LinkLmoModels(dir.path(), {10});
  if (!models) GTEST_SKIP() << "shared data (lmo-dev) not found; set LAYERMOD_DATA_DIR";
  const auto loaded = LoadSynthModels(*models, ListModelFiles(*models), {10});
  const ModelInfo& eggbox = loaded.at(10).info;
  EXPECT_DOUBLE_EQ(eggbox.diameter_mm, 164.628);
  EXPECT_EQ(eggbox.symmetries_discrete.size(), 1u);
  // The published diameter is the exact one of the mesh, to BOP's rounding.
  EXPECT_NEAR(ComputeModelInfo(10, loaded.at(10).mesh).diameter_mm, 164.628, 0.01);
}

}  // namespace
}  // namespace layermod
