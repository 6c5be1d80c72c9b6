// SPDX-License-Identifier: MIT
#include <layermod/archive.h>
#include <layermod/error.h>
#include <layermod/version.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "api_fixture.h"
#include "support/test_paths.h"

namespace layermod::api {
namespace {

TEST(ApiArchiveTest, LoadGivesWhatTrainingMade) {
  const test::ApiSample& sample = test::Sample();
  const Archive loaded = Archive::Load(sample.archive_path);
  EXPECT_EQ(loaded.template_count(), sample.archive.template_count());
  EXPECT_EQ(loaded.camera(), Camera::FromJson(test::SampleDir() / "camera.json"));
  ASSERT_EQ(loaded.objects().size(), 1u);
  const ArchiveObjectInfo object = loaded.objects().front();
  EXPECT_EQ(object.obj_id, 1);
  EXPECT_EQ(object.name, "bracket");
  EXPECT_EQ(object.layer_depths_mm.size(), 5u);
  EXPECT_EQ(object.templates, loaded.template_count());
  EXPECT_GT(object.diameter_mm, 100.0);
  EXPECT_EQ(loaded.InfoJson(), sample.archive.InfoJson());
}

TEST(ApiArchiveTest, SaveThenLoadKeepsTheInfo) {
  test::TempDir dir;
  test::Sample().archive.Save(dir / "copy.layermod");
  EXPECT_EQ(Archive::Load(dir / "copy.layermod").InfoJson(), test::Sample().archive.InfoJson());
}

TEST(ApiArchiveTest, CopiesShareOneArchive) {
  const Archive copy = test::Sample().archive;  // a handle: no template is copied
  EXPECT_EQ(copy.template_count(), test::Sample().archive.template_count());
}

TEST(ApiArchiveTest, MissingAndDamagedFilesThrowNamingTheFile) {
  test::TempDir dir;
  try {
    Archive::Load(dir / "missing.layermod");
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_NE(std::string(error.what()).find("missing.layermod"), std::string::npos);
  }
  std::ifstream in(test::Sample().archive_path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  std::ofstream(dir / "cut.layermod", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  EXPECT_THROW(Archive::Load(dir / "cut.layermod"), FormatError);
}

TEST(ApiVersionTest, NamesTheLibraryAndTheFormat) {
  EXPECT_FALSE(Version().empty());
  const auto info = nlohmann::json::parse(test::Sample().archive.InfoJson());
  EXPECT_EQ(info["format_version"].get<int>(), ArchiveFormatVersion());
  EXPECT_EQ(info["tool_version"].get<std::string>(), Version());
}

}  // namespace
}  // namespace layermod::api
