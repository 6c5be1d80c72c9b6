// SPDX-License-Identifier: MIT
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "mesh/model.h"
#include "mesh_files.h"
#include "support/matchers.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

using test::MatrixNear;

TEST(SaveModelPlyTest, RoundTripsThroughLoadModel) {
  test::TempDir dir;
  test::WriteTextFile(dir / "in.ply", test::CubePly(10, -3.0, true));
  const Model original = LoadModel(dir / "in.ply");
  SaveModelPly(dir / "out.ply", original.mesh);

  const std::string bytes = ReadFileBytes(dir / "out.ply");
  EXPECT_EQ(bytes.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
  EXPECT_NE(bytes.find("property float nx\n"), std::string::npos);
  EXPECT_NE(bytes.find("property uchar red\n"), std::string::npos);
  const std::size_t header_end = bytes.find("end_header\n") + 11;
  // 8 vertices of 6 floats + 3 bytes, 12 faces of a count byte + 3 int32.
  EXPECT_EQ(bytes.size() - header_end, 8u * 27u + 12u * 13u);

  const Model copy = LoadModel(dir / "out.ply");
  EXPECT_TRUE(copy.has_vertex_colors);
  ASSERT_EQ(copy.mesh.n_vertices(), original.mesh.n_vertices());
  EXPECT_EQ(copy.mesh.n_faces(), original.mesh.n_faces());
  EXPECT_NEAR(copy.sphere.radius_mm, original.sphere.radius_mm, 1e-6);
  EXPECT_THAT(copy.sphere.centre, MatrixNear(original.sphere.centre, 1e-6));
  // Same vertex order: the writer keeps indices, the loader keeps the file's order.
  for (const auto vh : copy.mesh.vertices()) {
    EXPECT_EQ(copy.mesh.color(vh), original.mesh.color(vh));
    EXPECT_LT((copy.mesh.point(vh) - original.mesh.point(vh)).norm(), 1e-6);
  }
}

TEST(SaveModelPlyTest, UnwritableTargetIsAnIoErrorAndLeavesNoFile) {
  test::TempDir dir;
  test::WriteTextFile(dir / "in.ply", test::CubePly(10));
  const Model model = LoadModel(dir / "in.ply");
  EXPECT_THROW(SaveModelPly(dir / "no_such_dir" / "out.ply", model.mesh), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir / "no_such_dir"));
}

}  // namespace
}  // namespace layermod
