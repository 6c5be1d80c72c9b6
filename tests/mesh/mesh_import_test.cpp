// SPDX-License-Identifier: MIT
#include "mesh/mesh_import.h"
#include "mesh/ply_header.h"
#include "support/thrown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

#include "mesh_files.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {
using ::testing::HasSubstr;
namespace fs = std::filesystem;

using test::ThrownMessage;

fs::path WriteFile(const test::TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

TEST(MeshImportTest, IsolatedAndInProcessImportsAgree) {
  test::TempDir dir;
  const fs::path path = WriteFile(dir, "cube.ply", test::CubePly(10));
  MeshImportOptions in_process;
  in_process.isolate = false;
  const TriangleSoup a = ImportTriangles(path, {});
  const TriangleSoup b = ImportTriangles(path, in_process);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.colors, b.colors);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangles.size(), 12u);
  EXPECT_EQ(a.positions.size(), 8u);
}

TEST(MeshImportTest, TheHelperIsFoundInTheBuildTree) {
  const fs::path importer = MeshImporterPath();
  ASSERT_FALSE(importer.empty());
  EXPECT_EQ(importer.filename(), kMeshImporterName);
}

// A flat n x n grid of vertices, 2 (n-1)^2 triangles.
std::string GridPly(int n) {
  std::ostringstream vertices, faces;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) vertices << x << ' ' << y << " 0\n";
  }
  for (int y = 0; y + 1 < n; ++y) {
    for (int x = 0; x + 1 < n; ++x) {
      const int i = y * n + x;
      faces << "3 " << i << ' ' << i + 1 << ' ' << i + n << "\n3 " << i + 1 << ' ' << i + n + 1
            << ' ' << i + n << '\n';
    }
  }
  return test::PlainPly(vertices.str(), n * n, faces.str(), 2 * (n - 1) * (n - 1));
}

char ProcessState(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return 'X';  // gone
  const auto paren = line.rfind(')');
  return paren + 2 < line.size() ? line[paren + 2] : '?';
}

TEST(MeshImportTest, TheHelperDoesNotOutliveItsCaller) {
  // The helper's output (about 0.5 MB) goes into a pipe nobody reads, so it blocks writing;
  // its caller, a shell, exits soon after starting it. The helper must go with it, not block
  // forever.
  test::TempDir dir;
  const fs::path mesh = WriteFile(dir, "grid.ply", GridPly(120));
  const std::string command =
      "sh -c '\"$0\" --units mm --max-triangles 100000 --parent $$ -- \"$1\" & echo $!; sleep "
      "0.3' " +
      MeshImporterPath().string() + " " + mesh.string();
  FILE* out = ::popen(command.c_str(), "r");
  ASSERT_NE(out, nullptr);
  int pid = 0;
  ASSERT_EQ(std::fscanf(out, "%d", &pid), 1);
  char state = ProcessState(pid);
  for (int i = 0; i < 100 && state != 'X' && state != 'Z'; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    state = ProcessState(pid);
  }
  if (state != 'X' && state != 'Z') ::kill(pid, SIGKILL);
  ::pclose(out);
  EXPECT_TRUE(state == 'X' || state == 'Z') << "helper " << pid << " still in state " << state;
}

TEST(MeshImportTest, HelperErrorsKeepTheirTypeAndMessage) {
  test::TempDir dir;
  EXPECT_THAT(ThrownMessage<IoError>([&] { ImportTriangles(dir / "missing.ply", {}); }),
              HasSubstr("missing.ply"));
  const fs::path garbage = WriteFile(dir, "garbage.stl", "solid x\nendsolid x\n");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { ImportTriangles(garbage, {}); }),
              HasSubstr("'" + garbage.string() + "'"));
}

TEST(MeshImportTest, SoupRoundTripsAndBrokenBytesAreRejected) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  soup.colors = {{{1, 2, 3}}, {{4, 5, 6}}, {{7, 8, 9}}};
  soup.triangles = {{0, 1, 2}};
  soup.has_colors = true;
  const std::string bytes = SerializeSoup(soup);
  const TriangleSoup back = ParseSoup(bytes, "m.ply");
  EXPECT_EQ(back.positions, soup.positions);
  EXPECT_EQ(back.colors, soup.colors);
  EXPECT_EQ(back.triangles, soup.triangles);
  EXPECT_TRUE(back.has_colors);
  EXPECT_THROW(ParseSoup(bytes.substr(0, bytes.size() - 1), "m.ply"), FormatError);
  EXPECT_THROW(ParseSoup("", "m.ply"), FormatError);
  std::string bad_index = bytes;
  bad_index[bad_index.size() - 4] = 9;  // last index of the triangle -> 9, out of range
  EXPECT_THAT(ThrownMessage<FormatError>([&] { ParseSoup(bad_index, "m.ply"); }),
              HasSubstr("out-of-range vertex index"));
}

TEST(MeshImportTest, AnImporterCrashIsAFormatErrorNamingTheFile) {
  // Found by the mesh fuzz target: assimp's OFF reader dies on this file.
  const fs::path path = test::SourceDir() / "tests/fuzz/regressions/mesh/assimp-off-crash.off";
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_FALSE(bytes.empty());
  test::TempDir dir;
  const fs::path off = WriteFile(dir, "part.off", bytes.substr(1));  // byte 0 picks the format
  const std::string message = ThrownMessage<FormatError>([&] { ImportTriangles(off, {}); });
  EXPECT_THAT(message, HasSubstr("'" + off.string() + "': the mesh importer crashed"));
}

TEST(MeshImportTest, PlyWithoutEndHeaderIsRefusedBeforeAssimpLoopsOnIt) {
  test::TempDir dir;
  const fs::path path = WriteFile(
      dir, "open.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n0 0 0\n");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { ImportTriangles(path, {}); }),
              HasSubstr("no end_header"));
}

TEST(MeshImportTest, PlyWhoseFirstLineIsNotExactlyPlyIsRefusedBeforeAssimpLoopsOnIt) {
  test::TempDir dir;
  const std::string body = "format ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n";
  const fs::path named_ply = WriteFile(dir, "near.ply", "ply!\n" + body);
  EXPECT_THAT(ThrownMessage<FormatError>([&] { ImportTriangles(named_ply, {}); }),
              HasSubstr("'" + named_ply.string() + "': not a PLY file"));
  const fs::path starts_with_ply = WriteFile(dir, "near.mesh", "ply\xff\xff\n" + body);
  EXPECT_THAT(ThrownMessage<FormatError>([&] { CheckPlyHeader(starts_with_ply, 10); }),
              HasSubstr("not a PLY file"));
  EXPECT_NO_THROW(CheckPlyHeader(WriteFile(dir, "part.off", "OFF\n0 0 0\n"), 10));
}

TEST(MeshImportTest, PlyHeadersAreCheckedForKeywordsTypesAndSizes) {
  test::TempDir dir;
  const std::string head = "ply\nformat binary_little_endian 1.0\n";
  const auto message = [&](const std::string& text) {
    return ThrownMessage<FormatError>([&] { ImportTriangles(WriteFile(dir, "h.ply", text), {}); });
  };
  EXPECT_THAT(message(head + "elephant 3\nend_header\n"), HasSubstr("unknown PLY header keyword"));
  EXPECT_THAT(message(head + "element vertex 3\nproperty quad x\nend_header\n"),
              HasSubstr("unknown PLY property type"));
  EXPECT_THAT(message("ply\nformat ascii 2.0\nend_header\n"), HasSubstr("unsupported PLY version"));
  EXPECT_THAT(message(head + "element vertex 1000000000\nproperty float x\nend_header\n"),
              HasSubstr("declares more data than the file holds"));
  MeshImportOptions options;
  options.max_triangles = 10;
  EXPECT_THAT(ThrownMessage<FormatError>([&] {
                ImportTriangles(WriteFile(dir, "f.ply",
                                          head + "element face 11\nproperty list uchar int "
                                                 "vertex_indices\nend_header\n"),
                                options);
              }),
              HasSubstr("declares 11 faces"));
}

}  // namespace
}  // namespace layermod
