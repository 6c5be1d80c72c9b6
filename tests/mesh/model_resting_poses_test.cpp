// SPDX-License-Identifier: MIT
#include "mesh/model_resting_poses.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/up_axis.h"
#include "mesh_files.h"
#include "support/test_paths.h"

namespace layermod {
namespace {

TEST(ModelRestingPosesTest, ACubeRestsOnEachSideAlike) {
  test::TempDir dir;
  const auto path = dir / "cube.ply";
  test::WriteTextFile(path, test::CubePly(20));
  const RestingPoses rest = SuggestRestingPoses(LoadModel(path));
  EXPECT_TRUE(rest.from_closed_mesh);
  ASSERT_EQ(rest.poses.size(), 6u);
  for (const RestingPose& pose : rest.poses) {
    EXPECT_NEAR(pose.probability, 1.0 / 6.0, 1e-9);
    EXPECT_NEAR(pose.stability_margin_mm, 10.0, 1e-9);
    EXPECT_TRUE(pose.axis_name.has_value());
  }
}

// The bundled bracket stands on its base plate, z up (see core/mesh/sample_part.cpp).
TEST(ModelRestingPosesTest, TheSampleBracketStandsOnItsBase) {
  const Model model = LoadModel(test::SourceDir() / "resources/sample/bracket.ply");
  const RestingPoses rest = SuggestRestingPoses(model);
  EXPECT_TRUE(rest.from_closed_mesh);
  const auto up = std::find_if(rest.poses.begin(), rest.poses.end(),
                               [](const RestingPose& pose) { return pose.axis_name == "+z"; });
  ASSERT_NE(up, rest.poses.end());
  EXPECT_GE(up->probability, kLikelyRestProbability);
  EXPECT_TRUE(IsLikelyRestingUp(rest, UprightFromUpAxis("+z")));
}

}  // namespace
}  // namespace layermod
