// SPDX-License-Identifier: MIT
#include "util/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {
namespace fs = std::filesystem;

int CountFiles(const fs::path& dir) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++count;
  return count;
}

TEST(AtomicFileTest, WritesAndReadsBack) {
  test::TempDir dir;
  WriteFileAtomically(dir / "a.bin", std::string("hello\0world", 11));
  EXPECT_EQ(ReadFileBytes(dir / "a.bin"), std::string("hello\0world", 11));
  EXPECT_EQ(CountFiles(dir.path()), 1);  // no temporary left behind
}

TEST(AtomicFileTest, ReplacesExistingFile) {
  test::TempDir dir;
  WriteFileAtomically(dir / "a.bin", "old");
  WriteFileAtomically(dir / "a.bin", "new content");
  EXPECT_EQ(ReadFileBytes(dir / "a.bin"), "new content");
}

TEST(AtomicFileTest, MissingDirectoryIsIoErrorNamingThePath) {
  test::TempDir dir;
  const fs::path target = dir / "no-such-dir/a.bin";
  try {
    WriteFileAtomically(target, "x");
    FAIL() << "expected IoError";
  } catch (const IoError& error) {
    EXPECT_NE(std::string(error.what()).find(target.string()), std::string::npos);
  }
  EXPECT_THROW(CheckWritableTarget(target), IoError);
}

TEST(AtomicFileTest, TargetThatIsADirectoryIsRejected) {
  test::TempDir dir;
  EXPECT_THROW(CheckWritableTarget(dir.path()), IoError);
  EXPECT_THROW(ReadFileBytes(dir.path()), IoError);
}

TEST(AtomicFileTest, MissingFileIsIoError) {
  EXPECT_THROW(ReadFileBytes("/nonexistent/layermod/file"), IoError);
}

}  // namespace
}  // namespace layermod
