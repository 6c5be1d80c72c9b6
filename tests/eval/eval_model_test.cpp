// SPDX-License-Identifier: MIT
#include "eval/eval_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dataset/models_info.h"
#include "mesh/model.h"
#include "mesh/sample_part.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// dataset/models with object 1 (plain) and object 2 (same mesh, declared symmetric about z).
fs::path WriteModels(const fs::path& dataset) {
  const fs::path models = dataset / "models";
  fs::create_directories(models);
  fs::create_directories(dataset / "test");
  SaveModelPly(models / "obj_000001.ply", MakeSampleBracket());
  SaveModelPly(models / "obj_000002.ply", MakeSampleBracket());
  std::map<int, ModelInfo> infos;
  infos[1].obj_id = 1;
  infos[1].diameter_mm = 140.0;
  infos[2].obj_id = 2;
  infos[2].diameter_mm = 150.0;
  infos[2].symmetries_continuous.push_back({});
  WriteModelsInfo(models / "models_info.json", infos);
  return models;
}

TEST(EvalModelTest, FindsTheModelsFolderFromTheRootOrASplit) {
  test::TempDir dir;
  const fs::path models = WriteModels(dir.path());
  EXPECT_EQ(FindBopModelsDir(dir.path()), models);
  EXPECT_EQ(FindBopModelsDir(dir / "test"), models);
  test::TempDir empty;
  try {
    FindBopModelsDir(empty / "test");
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_THAT(error.what(), HasSubstr("models_info.json"));
  }
}

TEST(EvalModelTest, LoadsPointsDiameterAndSymmetry) {
  test::TempDir dir;
  const auto models = LoadEvalModels(WriteModels(dir.path()), {1, 2});
  ASSERT_EQ(models.size(), 2u);
  EXPECT_FALSE(models.at(1).symmetric);
  EXPECT_TRUE(models.at(2).symmetric);
  EXPECT_EQ(models.at(2).diameter_mm, 150.0);
  const TriMesh bracket = MakeSampleBracket();
  EXPECT_EQ(models.at(1).points.size(), bracket.n_vertices());
  EXPECT_EQ(models.at(1).tree->size(), models.at(1).points.size());
}

TEST(EvalModelTest, UnknownObjectsAndMissingFilesAreNamed) {
  test::TempDir dir;
  const fs::path models = WriteModels(dir.path());
  try {
    LoadEvalModels(models, {7});
    FAIL() << "no exception";
  } catch (const FormatError& error) {
    EXPECT_THAT(error.what(), HasSubstr("models_info.json"));
    EXPECT_THAT(error.what(), HasSubstr("object 7"));
  }
  fs::remove(models / "obj_000002.ply");
  try {
    LoadEvalModels(models, {2});
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_THAT(error.what(), HasSubstr("obj_000002.ply"));
  }
}

}  // namespace
}  // namespace layermod
