// SPDX-License-Identifier: MIT
#include "features/feature_options.h"

#include <gtest/gtest.h>

#include <functional>

#include "util/error.h"

namespace layermod {
namespace {

TEST(FeatureOptionsTest, DefaultsAreValid) { EXPECT_NO_THROW(FeatureOptions{}.Validate()); }

TEST(FeatureOptionsTest, EachBadFieldIsRejected) {
  const std::vector<std::function<void(FeatureOptions&)>> breakers = {
      [](FeatureOptions& o) { o.color_features = -1; },
      [](FeatureOptions& o) { o.color_features = 0, o.normal_features = 0; },
      [](FeatureOptions& o) { o.normal_features = 9000; },
      [](FeatureOptions& o) { o.min_features = 0; },
      [](FeatureOptions& o) { o.weak_gradient = 0.0f; },
      [](FeatureOptions& o) { o.strong_gradient = 5.0f; },
      [](FeatureOptions& o) { o.max_normal_depth_step_mm = 0.0f; },
      [](FeatureOptions& o) {
        o.pyramid_levels = 5, o.spread_px = {5, 8, 8, 8, 8};
      },
      [](FeatureOptions& o) { o.spread_px = {5}; },
      [](FeatureOptions& o) {
        o.spread_px = {5, 0};
      },
      [](FeatureOptions& o) { o.depth_edge_fraction = 0.0f; },
  };
  for (size_t i = 0; i < breakers.size(); ++i) {
    FeatureOptions options;
    breakers[i](options);
    EXPECT_THROW(options.Validate(), Error) << "breaker " << i;
  }
}

TEST(FeatureOptionsTest, OneModalityAloneIsValid) {
  FeatureOptions options;
  options.color_features = 0;
  EXPECT_NO_THROW(options.Validate());
  options.color_features = 150;
  options.normal_features = 0;
  EXPECT_NO_THROW(options.Validate());
}

}  // namespace
}  // namespace layermod
