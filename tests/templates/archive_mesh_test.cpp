// SPDX-License-Identifier: MIT
#include "templates/archive_mesh.h"

#include <gtest/gtest.h>

#include <fstream>

#include "support/test_paths.h"

namespace layermod {
namespace {

// A 20 mm cube from x = y = z = 100 to 120: its sphere is far from the origin.
void WriteOffsetCube(const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
         "property float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 8; ++i) {
    out << 100 + 20 * (i & 1) << ' ' << 100 + 20 * ((i >> 1) & 1) << ' '
        << 100 + 20 * ((i >> 2) & 1) << '\n';
  }
  out << "3 0 2 1\n3 1 2 3\n3 4 5 6\n3 5 7 6\n3 0 1 4\n3 1 5 4\n"
         "3 2 6 3\n3 3 6 7\n3 0 4 2\n3 2 4 6\n3 1 3 5\n3 3 7 5\n";
}

ArchiveObject ObjectTrainedFrom(const Model& model) {
  ArchiveObject object;
  object.mesh_file = "cube.ply";
  object.mesh_hash = model.hash;
  object.sphere = model.sphere;
  return object;
}

TEST(ArchiveMeshTest, TheTrainingMeshMatchesItsObject) {
  const test::TempDir dir;
  WriteOffsetCube(dir / "cube.ply");
  const Model model = LoadModel(dir / "cube.ply");
  EXPECT_TRUE(ModelMatchesObject(model, ObjectTrainedFrom(model)));
}

TEST(ArchiveMeshTest, OtherBytesOrAnotherSphereDoNotMatch) {
  const test::TempDir dir;
  WriteOffsetCube(dir / "cube.ply");
  const Model model = LoadModel(dir / "cube.ply");
  ArchiveObject other_file = ObjectTrainedFrom(model);
  other_file.mesh_hash = "00";
  EXPECT_FALSE(ModelMatchesObject(model, other_file));
  ArchiveObject metres = ObjectTrainedFrom(model);
  metres.sphere.radius_mm *= 1000.0;
  EXPECT_FALSE(ModelMatchesObject(model, metres));
  ArchiveObject recentred = ObjectTrainedFrom(model);
  recentred.sphere.centre.setZero();
  EXPECT_FALSE(ModelMatchesObject(model, recentred));
}

TEST(ArchiveMeshTest, FindsTheMeshOnlyBesideTheArchive) {
  const test::TempDir dir;
  WriteOffsetCube(dir / "cube.ply");
  ArchiveObject object;
  object.mesh_file = "cube.ply";
  EXPECT_EQ(MeshBesideArchive(dir / "parts.layermod", object), dir / "cube.ply");
  object.mesh_file = "../" + dir.path().filename().string() + "/cube.ply";  // a path: name only
  EXPECT_EQ(MeshBesideArchive(dir / "parts.layermod", object), dir / "cube.ply");
  object.mesh_file = "missing.ply";
  EXPECT_FALSE(MeshBesideArchive(dir / "parts.layermod", object).has_value());
  object.mesh_file.clear();
  EXPECT_FALSE(MeshBesideArchive(dir / "parts.layermod", object).has_value());
}

TEST(ArchiveMeshTest, LoadsTheMeshRecentredWhenTheArchiveWasTrainedRecentred) {
  const test::TempDir dir;
  WriteOffsetCube(dir / "cube.ply");
  const Model as_is = LoadModel(dir / "cube.ply");
  ArchiveObject object = ObjectTrainedFrom(as_is);
  EXPECT_NEAR(LoadModelForObject(dir / "cube.ply", object).sphere.centre.x(), 110.0, 1e-6);
  object.sphere.centre.setZero();
  const Model recentred = LoadModelForObject(dir / "cube.ply", object);
  EXPECT_NEAR(recentred.sphere.centre.norm(), 0.0, 1e-6);
  EXPECT_TRUE(ModelMatchesObject(recentred, object));
}

}  // namespace
}  // namespace layermod
