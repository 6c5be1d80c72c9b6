// SPDX-License-Identifier: MIT
#include "eval/bop_targets.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

using ::testing::HasSubstr;

TEST(BopTargetsTest, ReadsTheBop19Layout) {
  test::TempDir dir;
  WriteFileAtomically(dir / "t.json", R"([{"im_id": 3, "inst_count": 2, "obj_id": 5,
                                          "scene_id": 1}, {"im_id": 4, "obj_id": 6, "scene_id": 2}])");
  const std::vector<BopTarget> targets = LoadBopTargets(dir / "t.json");
  ASSERT_EQ(targets.size(), 2u);
  EXPECT_EQ(targets[0].scene_id, 1);
  EXPECT_EQ(targets[0].image_id, 3);
  EXPECT_EQ(targets[0].obj_id, 5);
  EXPECT_EQ(targets[0].instance_count, 2);
  EXPECT_EQ(targets[1].instance_count, 1);
}

TEST(BopTargetsTest, ErrorsNameTheFile) {
  test::TempDir dir;
  try {
    LoadBopTargets(dir / "missing.json");
    FAIL() << "no exception";
  } catch (const IoError& error) {
    EXPECT_THAT(error.what(), HasSubstr("missing.json"));
  }
  WriteFileAtomically(dir / "bad.json", "{not json");
  EXPECT_THROW(LoadBopTargets(dir / "bad.json"), FormatError);
  WriteFileAtomically(dir / "noobj.json", R"([{"im_id": 3, "scene_id": 1}])");
  try {
    LoadBopTargets(dir / "noobj.json");
    FAIL() << "no exception";
  } catch (const FormatError& error) {
    EXPECT_THAT(error.what(), HasSubstr("noobj.json"));
    EXPECT_THAT(error.what(), HasSubstr("obj_id"));
  }
}

}  // namespace
}  // namespace layermod
