// SPDX-License-Identifier: MIT
// Resource limits: a 2-million-triangle CAD mesh trains within memory (it is simplified for
// rendering), and a run too large for memory is refused before any work with its estimate.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"

namespace layermod::test {
namespace {
namespace fs = std::filesystem;

template <typename T>
void Append(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// A finely tessellated sphere (radius 50 mm, resting on z = 0) as binary little-endian PLY:
// `rings` x `segments` vertices, 2 * (rings - 1) * segments triangles.
void WriteTessellatedSphere(const fs::path& path, int rings, int segments) {
  const int vertices = rings * segments;
  const long faces = 2L * (rings - 1) * segments;
  std::string bytes =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n";
  bytes.reserve(bytes.size() + vertices * 12L + faces * 13L);
  for (int i = 0; i < rings; ++i) {
    const double theta = 0.001 + (M_PI - 0.002) * i / (rings - 1);
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * M_PI * j / segments;
      Append(bytes, static_cast<float>(50.0 * std::sin(theta) * std::cos(phi)));
      Append(bytes, static_cast<float>(50.0 * std::sin(theta) * std::sin(phi)));
      Append(bytes, static_cast<float>(50.0 + 50.0 * std::cos(theta)));
    }
  }
  const auto triangle = [&bytes](int a, int b, int c) {
    Append(bytes, std::uint8_t{3});
    Append(bytes, a);
    Append(bytes, b);
    Append(bytes, c);
  };
  for (int i = 0; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j;
      const int b = i * segments + (j + 1) % segments;
      triangle(a, a + segments, b);
      triangle(b, a + segments, b + segments);
    }
  }
  std::ofstream(path, std::ios::binary) << bytes;
}

long PeakChildMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return usage.ru_maxrss / 1024;  // ru_maxrss is in KiB on Linux
}

std::string TrainArgs(const fs::path& mesh, const std::string& views, const fs::path& out) {
  return "train --model " + mesh.string() + " --camera " +
         (SourceDir() / "resources/sample/camera.json").string() + " " + views + " --out " +
         out.string();
}

TEST(HugeMeshTest, TwoMillionTrianglesTrainWithinMemory) {
  TempDir dir;
  WriteTessellatedSphere(dir / "dense.ply", 1001, 1000);  // 2,000,000 triangles
  const CliResult result = RunCli(SplitArgs(
      TrainArgs(dir / "dense.ply",
                "--dmin 600 --dmax 700 --azimuth 0:90:270 --elevation 30:30:60 --roll 0:10:0",
                dir / "dense.layermod")));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("of 2000000 triangles"), std::string::npos) << result.output;
  const CliResult inspected = RunCli({"inspect", (dir / "dense.layermod").string()});
  EXPECT_EQ(inspected.exit_code, 0) << inspected.output;
  RecordProperty("peak_memory_mib", static_cast<int>(PeakChildMemoryMiB()));
  EXPECT_LT(PeakChildMemoryMiB(), 4096);
}

TEST(HugeMeshTest, RunsTooLargeForMemoryAreRefusedBeforeTheWork) {
  TempDir dir;
  const CliResult result = RunCli(SplitArgs(TrainArgs(
      SourceDir() / "resources/sample/bracket.ply",
      "--dmin 300 --dmax 20000 --azimuth 0:0.5:359.5 --elevation 0:0.5:90 --roll -45:1:45",
      dir / "big.layermod")));
  EXPECT_EQ(result.exit_code, 1) << result.output;
  EXPECT_NE(result.output.find("MiB of memory"), std::string::npos) << result.output;
  EXPECT_EQ(result.output.find("rendering"), std::string::npos) << result.output;
  EXPECT_FALSE(fs::exists(dir / "big.layermod"));
  EXPECT_LT(PeakChildMemoryMiB(), 1024);  // refused from the plan, not after allocating views
}

}  // namespace
}  // namespace layermod::test
