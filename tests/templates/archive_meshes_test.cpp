// SPDX-License-Identifier: MIT
#include "templates/archive_meshes.h"

#include <gtest/gtest.h>

#include <functional>
#include <limits>

#include "archive_fixtures.h"
#include "support/test_paths.h"
#include "templates/archive_manifest.h"
#include "templates/byte_io.h"
#include "util/error.h"

namespace layermod {
namespace {

const TemplateArchive& Synthetic() {
  static const TemplateArchive archive = test::MakeSyntheticArchive();
  return archive;
}

const RenderMesh& Box() { return Synthetic().manifest().objects[0].mesh; }

// The synthetic archive with object 3's mesh replaced, packed without the writer's checks.
std::string WithMesh(const std::function<void(RenderMesh&)>& edit) {
  ArchiveManifest manifest = Synthetic().manifest();
  edit(manifest.objects[0].mesh);
  return test::PackUnchecked(manifest, Synthetic().templates());
}

TEST(ArchiveMeshesTest, LayoutIsPositionsThenColoursThenTriangles) {
  const std::string bytes = EncodeMesh(Box());
  ASSERT_EQ(bytes.size(), 8 * kMeshVertexBytes + 12 * kMeshTriangleBytes);
  ByteReader position(bytes, 3 * 12);  // vertex 3
  EXPECT_EQ(position.Get<float>(), Box().positions[3].x());
  ByteReader colour(bytes, 8 * 12 + 5 * 12 + 4);  // vertex 5, green
  EXPECT_EQ(colour.Get<float>(), Box().colors[5].y());
  ByteReader triangle(bytes, 8 * 24 + 11 * 12 + 8);  // triangle 11, third corner
  EXPECT_EQ(triangle.Get<std::uint32_t>(), Box().triangles[11][2]);
}

TEST(ArchiveMeshesTest, DecodeOfEncodeIsTheIdentity) {
  const std::string bytes = EncodeMesh(Box());
  const MeshInfo info = DescribeMesh("mesh_3.bin", Box(), bytes);
  EXPECT_EQ(info.vertex_count, 8u);
  EXPECT_EQ(info.triangle_count, 12u);
  EXPECT_EQ(info.crc32, Crc32(bytes));
  const RenderMesh decoded = DecodeMesh(bytes, info);
  EXPECT_EQ(decoded.positions, Box().positions);
  EXPECT_EQ(decoded.colors, Box().colors);
  EXPECT_EQ(decoded.triangles, Box().triangles);
  EXPECT_TRUE(DecodeMesh("", {"empty.bin", 0, 0, 0, 0}).positions.empty());
}

TEST(ArchiveMeshesTest, CountsMustMatchTheBytesBeforeAnyAllocation) {
  const std::string bytes = EncodeMesh(Box());
  EXPECT_THROW(DecodeMesh(bytes, {"m", 9, 12, bytes.size(), 0}), FormatError);
  EXPECT_THROW(DecodeMesh(bytes, {"m", 1ull << 60, 0, bytes.size(), 0}), FormatError);
  EXPECT_THROW(DecodeMesh(bytes, {"m", 8, (1ull << 62) + 12, bytes.size(), 0}), FormatError);
}

TEST(ArchiveMeshesTest, MeshesRoundTripThroughTheArchive) {
  const TemplateArchive loaded = ReadArchiveBytes(WithMesh([](RenderMesh&) {}), "a.layermod");
  EXPECT_EQ(loaded.Object(3).mesh.triangles, Box().triangles);
  EXPECT_EQ(loaded.Object(7).mesh.positions, Synthetic().manifest().objects[1].mesh.positions);
  const TemplateArchive empty =
      ReadArchiveBytes(WithMesh([](RenderMesh& mesh) { mesh = RenderMesh(); }), "a.layermod");
  EXPECT_TRUE(empty.Object(3).mesh.positions.empty());
}

TEST(ArchiveMeshesTest, BadMeshValuesAreRejected) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  test::ExpectRejected(WithMesh([](RenderMesh& mesh) { mesh.triangles[3][1] = 8; }),
                       "'mesh_3.bin': mesh triangle 3 uses vertex 8 of 8");
  test::ExpectRejected(WithMesh([&](RenderMesh& mesh) { mesh.positions[2].z() = nan; }),
                       "'mesh_3.bin': mesh vertex 2 is not finite");
  test::ExpectRejected(WithMesh([](RenderMesh& mesh) { mesh.colors[6].x() = 1.5f; }),
                       "'mesh_3.bin': mesh vertex 6 has a colour outside 0..1");
}

TEST(ArchiveMeshesTest, WriterRefusesBadMeshes) {
  ArchiveManifest manifest = Synthetic().manifest();
  manifest.objects[1].mesh.colors.pop_back();
  const TemplateArchive archive(manifest, Synthetic().templates());
  test::TempDir dir;
  try {
    WriteArchive(dir / "a.layermod", archive);
    FAIL() << "expected Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("object 7: mesh has 7 colours for 8 vertices"),
              std::string::npos)
        << error.what();
  }
}

TEST(ArchiveMeshesTest, MeshEntryProblemsAreRejected) {
  const std::string good = WithMesh([](RenderMesh&) {});
  test::UnpackedArchive missing = test::Unpack(good);
  missing.others.erase(missing.others.begin());
  test::ExpectRejected(test::Repack(missing, false), "mesh 'mesh_3.bin' is missing");

  test::UnpackedArchive damaged = test::Unpack(good);
  damaged.others[0].data[20] = static_cast<char>(damaged.others[0].data[20] ^ 0x40);
  test::ExpectRejected(test::Repack(damaged, false), "mesh 'mesh_3.bin' is damaged (CRC-32");

  test::UnpackedArchive counts = test::Unpack(good);
  counts.manifest["objects"][0]["mesh"]["vertex_count"] = 1ull << 50;
  test::ExpectRejected(test::Repack(counts, false),
                       "'mesh_3.bin': 1125899906842624 vertices and 12 triangles do not make");

  test::UnpackedArchive size = test::Unpack(good);
  size.manifest["objects"][1]["mesh"]["byte_size"] = 1ull << 40;
  test::ExpectRejected(test::Repack(size, false),
                       "mesh 'mesh_7.bin' holds 336 bytes, the manifest says 1099511627776");
}

}  // namespace
}  // namespace layermod
