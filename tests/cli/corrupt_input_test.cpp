// SPDX-License-Identifier: MIT
// Corrupt-input corpus through the real CLI: every broken archive, image, JSON file and mesh
// must end in a clear error that names the file, exit code 1, no crash and no output file.
// Inputs that are ugly but valid (non-manifold meshes, extra JSON fields) must still work.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/quoted.h"

namespace layermod::test {
namespace {
namespace fs = std::filesystem;

const fs::path& SampleMesh() {
  static const fs::path path = SourceDir() / "resources/sample/bracket.ply";
  return path;
}
const fs::path& SampleCamera() {
  static const fs::path path = SourceDir() / "resources/sample/camera.json";
  return path;
}

// Runs layermod and checks the contract for a broken input: exit 1 (not a signal, not a usage
// error), the output names `file`, and `output` was not created.
void ExpectCleanFailure(const std::vector<std::string>& args, const fs::path& file,
                        const fs::path& output) {
  const CliResult result = RunCli(args);
  EXPECT_EQ(result.exit_code, 1) << file << "\n" << result.output;
  EXPECT_NE(result.output.find(Quoted(file)), std::string::npos)
      << "the message does not name " << file << ":\n"
      << result.output;
  if (!output.empty()) {
    EXPECT_FALSE(fs::exists(output)) << output << " written for " << file;
  }
}

class CorruptInputTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    const CliResult trained = RunCli(SplitArgs(
        "train --model " + SampleMesh().string() + " --camera " + SampleCamera().string() +
        " --dmin 600 --dmax 700 --azimuth 0:120:240 --elevation 30:30:60 --roll 0:10:0 --out " +
        Path("good.layermod").string()));
    ASSERT_EQ(trained.exit_code, 0) << trained.output;
    WriteCapture();
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static fs::path Path(const std::string& name) { return *dir_ / name; }

  // A 640x480 capture matching the sample camera: a box on a table.
  static void WriteCapture() {
    cv::Mat depth(480, 640, CV_16U, cv::Scalar(900));
    cv::rectangle(depth, {280, 200, 80, 60}, cv::Scalar(750), cv::FILLED);
    cv::Mat color(480, 640, CV_8UC3, cv::Scalar(90, 110, 130));
    cv::rectangle(color, {280, 200, 80, 60}, cv::Scalar(200, 60, 40), cv::FILLED);
    ASSERT_TRUE(cv::imwrite(Path("depth.png").string(), depth));
    ASSERT_TRUE(cv::imwrite(Path("color.png").string(), color));
  }

  static std::vector<std::string> Inspect(const fs::path& archive) {
    return {"inspect", archive.string()};
  }
  static std::vector<std::string> Detect(const fs::path& color, const fs::path& depth,
                                         const fs::path& camera) {
    return {"detect",
            "--archive",
            Path("good.layermod").string(),
            "--color",
            color.string(),
            "--depth",
            depth.string(),
            "--camera",
            camera.string(),
            "--json",
            Path("det.json").string()};
  }
  static std::vector<std::string> Train(const fs::path& mesh, const std::string& extra = "") {
    return SplitArgs("train --model " + mesh.string() + " --camera " + SampleCamera().string() +
                     " --dmin 600 --dmax 700 --azimuth 0:180:180 --elevation 30:30:30 --roll "
                     "0:10:0 " +
                     extra + " --out " + Path("trained.layermod").string());
  }

  static TempDir* dir_;
};
TempDir* CorruptInputTest::dir_ = nullptr;

TEST_F(CorruptInputTest, TruncatedArchivesAtManyOffsetsFailCleanly) {
  const std::string bytes = ReadFileBytes(Path("good.layermod"));
  const fs::path broken = Path("truncated.layermod");
  for (std::size_t cut :
       {std::size_t{0}, std::size_t{1}, std::size_t{4}, std::size_t{30}, std::size_t{100}}) {
    WriteFileAtomically(broken, bytes.substr(0, cut));
    ExpectCleanFailure(Inspect(broken), broken, {});
  }
  for (int i = 1; i < 24; ++i) {
    WriteFileAtomically(broken, bytes.substr(0, bytes.size() * i / 24));
    ExpectCleanFailure(Inspect(broken), broken, {});
  }
  WriteFileAtomically(broken, bytes.substr(0, bytes.size() - 1));
  ExpectCleanFailure(Inspect(broken), broken, {});
}

TEST_F(CorruptInputTest, FlippedBytesAreRejectedOrHarmless) {
  const std::string bytes = ReadFileBytes(Path("good.layermod"));
  const fs::path broken = Path("flipped.layermod");
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> offset(0, bytes.size() - 1);
  int rejected = 0;
  for (int i = 0; i < 40; ++i) {
    std::string flipped = bytes;
    flipped[offset(rng)] ^= static_cast<char>(1 << (i % 8));
    WriteFileAtomically(broken, flipped);
    const CliResult result = RunCli(Inspect(broken));
    // A flip inside a zip field nothing depends on (a timestamp) may load; anything else fails.
    ASSERT_TRUE(result.exit_code == 0 || result.exit_code == 1) << result.output;
    if (result.exit_code == 1) {
      ++rejected;
      EXPECT_NE(result.output.find(Quoted(broken)), std::string::npos) << result.output;
    }
  }
  EXPECT_GE(rejected, 36);  // checksums cover every table and the manifest
}

TEST_F(CorruptInputTest, ForeignAndEmptyFilesAreNotArchives) {
  const fs::path broken = Path("foreign.layermod");
  for (const std::string& content :
       {std::string(), std::string("PK\x03\x04", 4), std::string(4096, '\0'),
        ReadFileBytes(SampleMesh()), ReadFileBytes(Path("color.png"))}) {
    WriteFileAtomically(broken, content);
    ExpectCleanFailure(Inspect(broken), broken, {});
  }
  ExpectCleanFailure(Inspect(*dir_ / "no-such.layermod"), *dir_ / "no-such.layermod", {});
}

TEST_F(CorruptInputTest, BrokenCaptureImagesFailCleanly) {
  const fs::path camera = SampleCamera();
  cv::Mat depth = cv::imread(Path("depth.png").string(), cv::IMREAD_ANYDEPTH);
  cv::Mat depth8;
  depth.convertTo(depth8, CV_8U, 0.2);
  cv::imwrite(Path("depth-8bit.png").string(), depth8);
  cv::Mat small;
  cv::resize(depth, small, {320, 240}, 0, 0, cv::INTER_NEAREST);
  cv::imwrite(Path("depth-small.png").string(), small);
  cv::imwrite(Path("depth-zero.png").string(), cv::Mat(480, 640, CV_16U, cv::Scalar(0)));
  cv::imwrite(Path("depth-nan.tiff").string(),
              cv::Mat(480, 640, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN())));
  cv::imwrite(Path("color-small.png").string(), cv::Mat(240, 320, CV_8UC3, cv::Scalar(9, 9, 9)));
  const std::string png = ReadFileBytes(Path("depth.png"));
  WriteFileAtomically(Path("depth-truncated.png"), png.substr(0, png.size() / 3));
  WriteFileAtomically(Path("depth-empty.png"), "");
  std::string huge = png;  // IHDR declares 2^31-1 x 2^31-1 pixels: refused before decoding
  for (std::size_t i = 16; i < 24; ++i) huge[i] = i % 4 == 0 ? '\x7f' : '\xff';
  WriteFileAtomically(Path("depth-huge-header.png"), huge);

  for (const char* name :
       {"depth-8bit.png", "depth-small.png", "depth-zero.png", "depth-nan.tiff",
        "depth-truncated.png", "depth-empty.png", "depth-huge-header.png", "missing-depth.png"}) {
    ExpectCleanFailure(Detect(Path("color.png"), Path(name), camera), Path(name), Path("det.json"));
  }
  for (const char* name : {"color-small.png", "depth-truncated.png", "missing-color.png"}) {
    ExpectCleanFailure(Detect(Path(name), Path("depth.png"), camera), Path(name), Path("det.json"));
  }
}

TEST_F(CorruptInputTest, BrokenCameraFilesFailCleanly) {
  const std::vector<std::string> broken_json = {
      "",
      "{",
      "[1, 2, 3]",
      R"({"fx": "572", "fy": 572, "cx": 319.5, "cy": 239.5, "width": 640, "height": 480})",
      R"({"fx": -572, "fy": 572, "cx": 319.5, "cy": 239.5, "width": 640, "height": 480})",
      R"({"fx": 572, "fy": 572, "cx": 319.5, "cy": 239.5, "width": 640})",
      R"({"fx": 1e999, "fy": 572, "cx": 319.5, "cy": 239.5, "width": 640, "height": 480})",
      R"({"fx": 572, "fy": 572, "cx": 319.5, "cy": 239.5, "width": 640.5, "height": 480})",
      R"({"fx": 572, "fy": 572, "cx": 319.5, "cy": 239.5, "width": 64000000, "height": 480})",
  };
  const fs::path camera = Path("camera-broken.json");
  for (const std::string& text : broken_json) {
    WriteFileAtomically(camera, text);
    ExpectCleanFailure(Detect(Path("color.png"), Path("depth.png"), camera), camera,
                       Path("det.json"));
  }
}

TEST_F(CorruptInputTest, ExtraCameraFieldsAreIgnored) {
  const fs::path camera = Path("camera-extra.json");
  WriteFileAtomically(camera, R"({"fx": 572.0, "fy": 572.0, "cx": 319.5, "cy": 239.5,
      "width": 640, "height": 480, "depth_scale": 1.0, "serial": "A17", "notes": [1, 2]})");
  const CliResult result = RunCli(Detect(Path("color.png"), Path("depth.png"), camera));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_TRUE(fs::exists(Path("det.json")));
  fs::remove(Path("det.json"));
}

TEST_F(CorruptInputTest, BrokenProfilesFailCleanly) {
  const std::vector<std::string> broken_profiles = {
      "",
      "{\"depth_min_mm\": ",
      R"({"depth_min_mm": "near"})",
      R"({"depth_min_mm": 900, "depth_max_mm": 600})",
      R"({"views": {"azimuth": "0:0:90"}})",
      R"({"views": {"azimuth": "0:0.001:359", "elevation": "0:0.001:90", "roll": "-45:0.001:45"}})",
      R"({"features": {"color_features": -3}})",
      R"({"features": {"color_features": 1e12}})",
  };
  const fs::path profile = Path("profile-broken.json");
  for (const std::string& text : broken_profiles) {
    WriteFileAtomically(profile, text);
    const CliResult result = RunCli(SplitArgs(
        "train --model " + SampleMesh().string() + " --camera " + SampleCamera().string() +
        " --profile " + profile.string() + " --out " + Path("trained.layermod").string()));
    EXPECT_EQ(result.exit_code, 1) << text << "\n" << result.output;
    EXPECT_FALSE(fs::exists(Path("trained.layermod"))) << text;
    fs::remove(Path("trained.layermod"));
  }
}

std::string AsciiPly(const std::string& vertices, int vertex_count, const std::string& faces,
                     int face_count) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertex_count) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(face_count) + "\nproperty list uchar int vertex_indices\nend_header\n" +
         vertices + faces;
}

TEST_F(CorruptInputTest, BrokenMeshesFailCleanly) {
  const std::string bracket = ReadFileBytes(SampleMesh());
  const std::vector<std::pair<std::string, std::string>> meshes = {
      {"empty.ply", ""},
      {"truncated.ply", bracket.substr(0, bracket.size() / 2)},
      {"header-only.ply", bracket.substr(0, bracket.find("end_header") + 11)},
      {"nan.ply", AsciiPly("0 0 0\nnan 10 0\n0 0 10\n", 3, "3 0 1 2\n", 1)},
      {"inf.ply", AsciiPly("0 0 0\n10 inf 0\n0 0 10\n", 3, "3 0 1 2\n", 1)},
      {"zero-area.ply", AsciiPly("0 0 0\n10 0 0\n20 0 0\n", 3, "3 0 1 2\n3 0 0 1\n", 2)},
      {"bad-index.ply", AsciiPly("0 0 0\n10 0 0\n0 10 0\n", 3, "3 0 1 7\n", 1)},
      {"no-faces.stl", "solid x\nendsolid x\n"},
      {"garbage.obj", std::string("\x7f"
                                  "ELF binary junk \x01\x02\x03")},
  };
  for (const auto& [name, content] : meshes) {
    WriteFileAtomically(Path(name), content);
    ExpectCleanFailure(Train(Path(name)), Path(name), Path("trained.layermod"));
  }
}

TEST_F(CorruptInputTest, NonManifoldMeshesStillTrain) {
  // Two tetrahedra sharing one edge with a third face on it, a dangling triangle, one face
  // flipped and one degenerate face: CAD exports look like this and must still train.
  const std::string vertices =
      "0 0 0\n40 0 0\n0 40 0\n0 0 40\n0 -40 0\n0 0 -40\n60 60 60\n60 61 60\n61 60 60\n";
  const std::string faces =
      "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 4 1\n3 0 1 5\n3 6 7 8\n3 0 0 1\n";
  WriteFileAtomically(Path("non-manifold.ply"), AsciiPly(vertices, 9, faces, 8));
  const CliResult result = RunCli(Train(Path("non-manifold.ply")));
  EXPECT_EQ(result.exit_code, 0) << result.output;
  EXPECT_EQ(RunCli(Inspect(Path("trained.layermod"))).exit_code, 0);
  fs::remove(Path("trained.layermod"));
}

}  // namespace
}  // namespace layermod::test
