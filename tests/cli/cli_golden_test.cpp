// SPDX-License-Identifier: MIT
// Golden CLI tests: one line of cases.txt per case. On mismatch the actual output is written
// beside the build's test binary as <case>.actual.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_runner.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"

namespace layermod::test {
namespace {
namespace fs = std::filesystem;

struct CliCase {
  std::string name;
  int exit_code = 0;
  std::string expected_text;
  std::string args;
};

// Test names show the case's name, not a byte dump of the struct.
void PrintTo(const CliCase& c, std::ostream* os) { *os << c.name; }

std::string Trim(const std::string& text) {
  const auto begin = text.find_first_not_of(' ');
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(' ') - begin + 1);
}

std::vector<CliCase> LoadCases() {
  std::ifstream in(LAYERMOD_CLI_CASES);
  std::vector<CliCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, '|')) fields.push_back(Trim(field));
    if (fields.size() == 3) fields.emplace_back();
    if (fields.size() != 4) throw std::runtime_error("bad case line: " + line);
    cases.push_back({fields[0], std::stoi(fields[1]), fields[2], fields[3]});
  }
  return cases;
}

std::string Substitute(std::string text, const std::string& key, const std::string& value) {
  for (auto pos = text.find(key); pos != std::string::npos; pos = text.find(key, pos)) {
    text.replace(pos, key.size(), value);
    pos += value.size();
  }
  return text;
}

// Fixture files the cases refer to, written into {TMP}.
void WriteFixtures(const fs::path& dir) {
  WriteFileAtomically(dir / "empty.ply", "");
  WriteFileAtomically(dir / "garbage.ply", "\x01\x02 this is not a mesh \xff\xfe");
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  WriteFileAtomically(dir / "nan.ply", header + "0 0 0\nnan 1 0\n0 0 1\n3 0 1 2\n");
  WriteFileAtomically(dir / "flat-line.ply", header + "0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
  WriteFileAtomically(dir / "nocam.json", R"({"fx": 500, "fy": 500, "cx": 320, "cy": 240,
                                              "width": 640})");
  const CliResult trained = RunCli(SplitArgs(
      "train --model " + (SourceDir() / "resources/sample/bracket.ply").string() + " --camera " +
      (SourceDir() / "resources/sample/camera.json").string() +
      " --dmin 600 --dmax 700 --azimuth 0:120:240 --elevation 30:30:60 --roll 0:10:0 --out " +
      (dir / "tiny.layermod").string()));
  if (trained.exit_code != 0)
    throw std::runtime_error("fixture training failed: " + trained.output);
  std::string bytes = ReadFileBytes(dir / "tiny.layermod");
  WriteFileAtomically(dir / "truncated.layermod", bytes.substr(0, bytes.size() / 2));
  for (std::size_t i = bytes.size() / 3; i < bytes.size(); i += 101) bytes[i] ^= 0x5a;
  WriteFileAtomically(dir / "corrupt.layermod", bytes);
}

class CliGoldenTest : public ::testing::TestWithParam<CliCase> {
 protected:
  static void SetUpTestSuite() {
    temp_ = new TempDir();
    WriteFixtures(temp_->path());
  }
  static void TearDownTestSuite() {
    delete temp_;
    temp_ = nullptr;
  }
  static TempDir* temp_;
};
TempDir* CliGoldenTest::temp_ = nullptr;

TEST_P(CliGoldenTest, ExitCodeAndOutput) {
  const CliCase& c = GetParam();
  auto expand = [&](const std::string& text) {
    return Substitute(Substitute(text, "{SRC}", SourceDir().string()), "{TMP}",
                      temp_->path().string());
  };
  const CliResult result = RunCli(SplitArgs(expand(c.args)));
  const std::string expected = expand(c.expected_text);
  const bool ok =
      result.exit_code == c.exit_code && result.output.find(expected) != std::string::npos;
  if (!ok) {
    std::ofstream(c.name + ".actual") << "exit " << result.exit_code << '\n' << result.output;
  }
  EXPECT_EQ(result.exit_code, c.exit_code) << result.output;
  EXPECT_NE(result.output.find(expected), std::string::npos)
      << "expected to find: " << expected << "\nactual output:\n"
      << result.output;
  // A failed command never leaves an output archive behind.
  if (c.exit_code != 0) {
    EXPECT_FALSE(fs::exists(temp_->path() / "a.layermod"));
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, CliGoldenTest, ::testing::ValuesIn(LoadCases()),
                         [](const ::testing::TestParamInfo<CliCase>& param_info) {
                           return param_info.param.name;
                         });

}  // namespace
}  // namespace layermod::test
