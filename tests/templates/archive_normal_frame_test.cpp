// SPDX-License-Identifier: MIT
// The frame depth normals were quantized in travels with the archive: format 3 archives say it in
// their profile; older ones, which did not, read as camera-frame archives.
#include <gtest/gtest.h>

#include <string>

#include "archive_fixtures.h"
#include "support/test_paths.h"
#include "templates/archive.h"
#include "util/atomic_file.h"

namespace layermod {
namespace {

std::string Bytes(const TemplateArchive& archive) {
  test::TempDir dir;
  WriteArchive(dir / "frame.layermod", archive);
  return ReadFileBytes(dir / "frame.layermod");
}

NormalFrame FrameOf(const TemplateArchive& archive) {
  return archive.manifest().objects.at(0).profile.features.normal_frame;
}

TEST(ArchiveNormalFrameTest, NewArchivesSayTheirFrameAndReadItBack) {
  const TemplateArchive archive = test::MakeSyntheticArchive();
  ASSERT_EQ(FrameOf(archive), NormalFrame::kViewingRay);
  const std::string bytes = Bytes(archive);
  const test::UnpackedArchive unpacked = test::Unpack(bytes);
  EXPECT_EQ(unpacked.manifest["objects"][0]["profile"]["features"]["normal_frame"], "viewing_ray");
  EXPECT_EQ(FrameOf(ReadArchiveBytes(bytes, "new.layermod")), NormalFrame::kViewingRay);

  ArchiveManifest manifest = archive.manifest();
  for (ArchiveObject& object : manifest.objects) {
    object.profile.features.normal_frame = NormalFrame::kCamera;
  }
  const TemplateArchive camera_frame(manifest, archive.templates());
  EXPECT_EQ(FrameOf(ReadArchiveBytes(Bytes(camera_frame), "camera.layermod")),
            NormalFrame::kCamera);
}

TEST(ArchiveNormalFrameTest, VersionTwoArchivesReadAsCameraFrameOnes) {
  test::UnpackedArchive unpacked = test::Unpack(Bytes(test::MakeSyntheticArchive()));
  unpacked.manifest["format_version"] = 2;
  for (auto& object : unpacked.manifest["objects"]) {
    object["profile"]["features"].erase("normal_frame");
  }
  const TemplateArchive loaded = ReadArchiveBytes(test::Repack(unpacked), "old.layermod");
  EXPECT_EQ(loaded.manifest().format_version, 2);
  for (const ArchiveObject& object : loaded.manifest().objects) {
    EXPECT_EQ(object.profile.features.normal_frame, NormalFrame::kCamera);
  }
}

TEST(ArchiveNormalFrameTest, AnUnknownFrameIsRefusedByName) {
  test::UnpackedArchive unpacked = test::Unpack(Bytes(test::MakeSyntheticArchive()));
  unpacked.manifest["objects"][0]["profile"]["features"]["normal_frame"] = "sideways";
  test::ExpectRejected(test::Repack(unpacked),
                       "field 'features.normal_frame' must be \"camera\" or \"viewing_ray\"");
}

}  // namespace
}  // namespace layermod
