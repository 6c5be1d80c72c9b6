// SPDX-License-Identifier: MIT
#include "synth/synth_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "synth_fixtures.h"
#include "util/error.h"

namespace layermod {
namespace {

using ::testing::HasSubstr;

std::string ErrorOf(const std::function<void(SynthOptions&)>& change) {
  SynthOptions options = test::SmallOptions("models", {1}, 3, "out");
  change(options);
  try {
    options.Validate();
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(SynthOptionsTest, DefaultsWithACameraAreValid) {
  EXPECT_EQ(ErrorOf([](SynthOptions&) {}), "");
  const SynthOptions defaults;
  EXPECT_EQ(defaults.dmin_mm, 650.0);
  EXPECT_EQ(defaults.dmax_mm, 1150.0);
  EXPECT_EQ(defaults.elevation_min_deg, 10.0);
  EXPECT_EQ(defaults.elevation_max_deg, 88.0);
  EXPECT_EQ(defaults.roll_max_deg, 45.0);
  EXPECT_EQ(defaults.min_target_visibility, 0.6);
}

TEST(SynthOptionsTest, NamesTheBadOption) {
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.obj_ids.clear(); }),
              HasSubstr("at least one target"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.obj_ids = {0}; }), HasSubstr("must be positive"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.scenes = 0; }),
              HasSubstr("number of scenes must be positive (got 0)"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.scenes = -4; }), HasSubstr("got -4"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.dmin_mm = 1200.0; }),
              HasSubstr("must be less than dmax"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.dmin_mm = 0.0; }), HasSubstr("positive"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.elevation_max_deg = 90.0; }), HasSubstr("elevation"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.clutter = 6; }), HasSubstr("clutter must be 0..5"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.min_target_visibility = 1.5; }),
              HasSubstr("visibility"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.models_dir.clear(); }), HasSubstr("models folder"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.out_dir.clear(); }), HasSubstr("output folder"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.camera = {}; }), HasSubstr("camera"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.noise.baseline_mm = 0.0; }), HasSubstr("baseline"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.noise.min_range_mm = 5000.0; }),
              HasSubstr("sensor range"));
  EXPECT_THAT(ErrorOf([](SynthOptions& o) { o.noise.edge_drop_probability = 2.0; }),
              HasSubstr("edge drop probability"));
}

}  // namespace
}  // namespace layermod
