// SPDX-License-Identifier: MIT
#include "dataset/models_info.h"
#include "support/thrown.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "bop_fixtures.h"
#include "support/matchers.h"
#include "support/test_paths.h"
#include "util/error.h"

namespace layermod {
namespace {

namespace fs = std::filesystem;
using test::MatrixNear;
using ::testing::AllOf;
using ::testing::HasSubstr;

using test::ThrownMessage;

TEST(ModelsInfoTest, ReadsTheRealLineModModels) {
  const auto data = test::SharedDataDir();
  if (!data) GTEST_SKIP() << "shared data (lmo-dev) not found; set LAYERMOD_DATA_DIR";
  const std::map<int, ModelInfo> infos =
      LoadModelsInfo(*data / "lmo-dev" / "models" / "models_info.json");
  ASSERT_EQ(infos.size(), 8u);
  EXPECT_DOUBLE_EQ(infos.at(1).diameter_mm, 102.099);
  EXPECT_DOUBLE_EQ(infos.at(8).diameter_mm, 261.472);
  EXPECT_DOUBLE_EQ(infos.at(1).min.x(), -37.9343);
  EXPECT_DOUBLE_EQ(infos.at(1).size.z(), 91.769);
  // Eggbox (10) and glue (11) are symmetric under a half turn; the others are not.
  for (const auto& [obj_id, info] : infos) {
    EXPECT_EQ(info.obj_id, obj_id);
    EXPECT_EQ(info.IsSymmetric(), obj_id == 10 || obj_id == 11) << obj_id;
  }
  ASSERT_EQ(infos.at(10).symmetries_discrete.size(), 1u);
  const Pose& eggbox = infos.at(10).symmetries_discrete[0];
  EXPECT_DOUBLE_EQ(eggbox.R(0, 0), -0.999964);
  EXPECT_DOUBLE_EQ(eggbox.t.x(), 0.232611);
  EXPECT_DOUBLE_EQ(eggbox.t.y(), 0.694388);
  EXPECT_NEAR(eggbox.R.determinant(), 1.0, 1e-4);
  ASSERT_EQ(infos.at(11).symmetries_discrete.size(), 1u);
  EXPECT_DOUBLE_EQ(infos.at(11).symmetries_discrete[0].R(1, 1), -0.999644);
}

TEST(ModelsInfoTest, WriteThenReadIsExact) {
  test::TempDir dir;
  ModelInfo info;
  info.obj_id = 4;
  info.diameter_mm = 123.456789;
  info.min = {-1.5, -2.5, -3.5};
  info.size = {3.0, 5.0, 7.0};
  Pose half_turn;
  half_turn.R = Eigen::AngleAxisd(kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  half_turn.t = {0.25, -0.5, 0.0};
  info.symmetries_discrete.push_back(half_turn);
  info.symmetries_continuous.push_back({Eigen::Vector3d::UnitZ(), Eigen::Vector3d(0, 0, 1.5)});
  ModelInfo plain;
  plain.obj_id = 12;
  plain.diameter_mm = 50.0;
  WriteModelsInfo(dir / "models_info.json", {{4, info}, {12, plain}});

  const std::map<int, ModelInfo> read = LoadModelsInfo(dir / "models_info.json");
  ASSERT_EQ(read.size(), 2u);
  const ModelInfo& got = read.at(4);
  EXPECT_EQ(got.diameter_mm, info.diameter_mm);
  EXPECT_EQ(got.min, info.min);
  EXPECT_EQ(got.size, info.size);
  ASSERT_EQ(got.symmetries_discrete.size(), 1u);
  EXPECT_EQ(got.symmetries_discrete[0].R, half_turn.R);
  EXPECT_EQ(got.symmetries_discrete[0].t, half_turn.t);
  ASSERT_EQ(got.symmetries_continuous.size(), 1u);
  EXPECT_THAT(got.symmetries_continuous[0].offset, MatrixNear(Eigen::Vector3d(0, 0, 1.5), 0.0));
  EXPECT_FALSE(read.at(12).IsSymmetric());
}

TEST(ModelsInfoTest, ErrorsNameTheFileObjectAndField) {
  test::TempDir dir;
  const fs::path path = dir / "models_info.json";
  test::WriteText(path, "{\"1\": {\"min_x\": 0}}");
  EXPECT_THAT(
      ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
      AllOf(HasSubstr(path.string()), HasSubstr("object 1"), HasSubstr("'diameter' is missing")));
  test::WriteText(path, "{\"1\": {\"diameter\": -3}}");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
              HasSubstr("'diameter' must be positive"));
  test::WriteText(path, "{\"1\": {\"diameter\": 3, \"symmetries_discrete\": [[1, 0, 0]]}}");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
              AllOf(HasSubstr("symmetries_discrete[0]"), HasSubstr("must be 16 numbers")));
  test::WriteText(path,
                  "{\"1\": {\"diameter\": 3, \"symmetries_discrete\": "
                  "[[2,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]]}}");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
              HasSubstr("not a rotation"));
  test::WriteText(path, "{\"one\": {\"diameter\": 3}}");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
              HasSubstr("key 'one' is not a non-negative integer id"));
  test::WriteText(path, "{\"1\": ");
  EXPECT_THAT(ThrownMessage<FormatError>([&] { LoadModelsInfo(path); }),
              HasSubstr("malformed JSON"));
  EXPECT_THAT(ThrownMessage<IoError>([&] { LoadModelsInfo(dir / "missing.json"); }),
              HasSubstr("missing.json"));
}

TEST(PointSetDiameterTest, CubeCornersGiveTheSpaceDiagonal) {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 10 : 0, i & 2 ? 20 : 0, i & 4 ? 30 : 0);
  EXPECT_DOUBLE_EQ(PointSetDiameter(corners), std::sqrt(100.0 + 400.0 + 900.0));
  EXPECT_EQ(PointSetDiameter({Eigen::Vector3d::Zero()}), 0.0);
}

TEST(PointSetDiameterTest, MatchesBruteForceOnRandomClouds) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < 400; ++i) {
      points.emplace_back(normal(rng) * 30.0, normal(rng) * 10.0, normal(rng) * (trial + 1));
    }
    double brute = 0.0;
    for (const auto& a : points) {
      for (const auto& b : points) brute = std::max(brute, (a - b).norm());
    }
    EXPECT_DOUBLE_EQ(PointSetDiameter(points), brute);
  }
}

}  // namespace
}  // namespace layermod
