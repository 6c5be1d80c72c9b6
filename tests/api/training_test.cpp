// SPDX-License-Identifier: MIT
#include <layermod/error.h>
#include <layermod/training.h>

#include <gtest/gtest.h>

#include "api_fixture.h"
#include "support/test_paths.h"

namespace layermod::api {
namespace {

TrainOptions Tiny() {
  TrainOptions options;
  options.model = test::SampleDir() / "bracket.ply";
  options.camera = Camera::FromJson(test::SampleDir() / "camera.json");
  options.profile_json =
      R"({"depth_min_mm": 700, "depth_max_mm": 800, "views": {"even_spacing_deg": 40,
          "roll": {"min_deg": 0, "step_deg": 15, "max_deg": 0}}})";
  return options;
}

TEST(ApiTrainingTest, ReportsProgressUpToEveryTemplate) {
  std::size_t last_done = 0;
  std::size_t last_total = 0;
  const Archive archive = Train(Tiny(), [&](std::size_t done, std::size_t total, std::string_view) {
    last_done = done;
    last_total = total;
  });
  EXPECT_GT(archive.template_count(), 0u);
  EXPECT_EQ(last_done, archive.template_count());
  EXPECT_EQ(last_total, archive.template_count());
  EXPECT_EQ(archive.objects().at(0).name, "bracket");  // from the mesh file's name
}

TEST(ApiTrainingTest, CancelFlagStopsAndWritesNothing) {
  test::TempDir dir;
  TrainOptions options = Tiny();
  options.out = dir / "never.layermod";
  std::atomic<bool> cancel{false};
  EXPECT_THROW(Train(
                   options,
                   [&](std::size_t done, std::size_t, std::string_view) {
                     if (done >= 3) cancel = true;
                   },
                   &cancel),
               Cancelled);
  EXPECT_FALSE(std::filesystem::exists(options.out));
}

TEST(ApiTrainingTest, BadInputThrowsNamingIt) {
  TrainOptions options = Tiny();
  options.profile_json = R"({"depth_min_mm": -5})";
  EXPECT_THROW(Train(options), FormatError);
  options = Tiny();
  options.profile_json = "{not json";
  EXPECT_THROW(Train(options), FormatError);
  options = Tiny();
  options.model = "/nonexistent/part.ply";
  EXPECT_THROW(Train(options), IoError);
  options = Tiny();
  options.camera.fx = 0.0;
  EXPECT_THROW(Train(options), Error);
  options = Tiny();
  options.units = "inch";
  EXPECT_THROW(Train(options), Error);
}

}  // namespace
}  // namespace layermod::api
