// SPDX-License-Identifier: MIT
#include "templates/training_profile.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "geometry/up_axis.h"
#include "support/test_paths.h"
#include "util/atomic_file.h"
#include "util/error.h"

namespace layermod {
namespace {

TrainingProfile Unusual() {
  TrainingProfile profile;
  profile.depth_min_mm = 515.25;
  profile.depth_max_mm = 1450.125;
  profile.views.azimuth = {-10.5, 0.1, 350.0};
  profile.views.elevation = {-45.0, 10.0, 45.0};
  profile.views.roll = {-45.0, 1.0 / 3.0, 45.0};  // needs every digit to round-trip
  profile.views.even_spacing_deg = 0.0;
  profile.features.color_features = 100;
  profile.features.normal_features = 0;
  profile.features.min_features = 20;
  profile.features.weak_gradient = 0.1f;
  profile.features.strong_gradient = 33.3f;
  profile.features.max_normal_depth_step_mm = 25.5f;
  profile.features.pyramid_levels = 3;
  profile.features.spread_px = {4, 6, 8};
  profile.features.depth_edge_fraction = 0.25f;
  return profile;
}

void ExpectSameProfile(const TrainingProfile& actual, const TrainingProfile& expected) {
  EXPECT_EQ(actual.depth_min_mm, expected.depth_min_mm);
  EXPECT_EQ(actual.depth_max_mm, expected.depth_max_mm);
  EXPECT_EQ(actual.views, expected.views);
  EXPECT_EQ(actual.features, expected.features);
}

void ExpectFormatError(const nlohmann::json& json, const std::string& phrase) {
  try {
    TrainingProfileFromJson(json);
    ADD_FAILURE() << "accepted: " << json.dump();
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find(phrase), std::string::npos)
        << "message: " << error.what() << "\nexpected: " << phrase;
  }
}

TEST(TrainingProfileTest, DefaultsCoverTheEvaluationEnvelope) {
  const TrainingProfile profile;
  EXPECT_NO_THROW(profile.Validate());
  EXPECT_LE(profile.depth_min_mm, 500.0);
  EXPECT_GE(profile.depth_max_mm, 1500.0);
  const ViewSamplingOptions views = TrainingProfile::DefaultEnvelopeViews();
  EXPECT_EQ(views.elevation, (AngleRange{0.0, 15.0, 90.0}));
  EXPECT_EQ(views.azimuth, (AngleRange{0.0, 15.0, 345.0}));
  EXPECT_EQ(views.roll, (AngleRange{-45.0, 15.0, 45.0}));
  EXPECT_EQ(views.even_spacing_deg, 12.0);
  EXPECT_EQ(profile.views, views);
}

TEST(TrainingProfileTest, ValidateNamesTheBadField) {
  TrainingProfile profile;
  profile.depth_min_mm = 0.0;
  EXPECT_THROW(profile.Validate(), Error);
  profile.depth_min_mm = 1500.0;  // == depth_max_mm
  try {
    profile.Validate();
    FAIL() << "expected Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("depth_min_mm must be below depth_max_mm"),
              std::string::npos);
  }
  profile = TrainingProfile();
  profile.features.spread_px = {5};
  EXPECT_THROW(profile.Validate(), Error);
  profile = TrainingProfile();
  profile.views.roll.step_deg = 0.0;
  EXPECT_THROW(profile.Validate(), Error);
}

TEST(TrainingProfileTest, JsonRoundTripIsExact) {
  const TrainingProfile profile = Unusual();
  const nlohmann::json json = ToJson(profile);
  ExpectSameProfile(TrainingProfileFromJson(nlohmann::json::parse(json.dump())), profile);
  ExpectSameProfile(TrainingProfileFromJson(ToJson(TrainingProfile())), TrainingProfile());
}

TEST(TrainingProfileTest, JsonIsReadable) {
  const nlohmann::json json = ToJson(TrainingProfile());
  EXPECT_EQ(json["views"]["elevation"], "0:15:90");
  EXPECT_EQ(json["views"]["roll"], "-45:15:45");
  EXPECT_EQ(json["features"]["depth_edge_fraction"].dump(), "0.3");  // not 0.30000001192...
  EXPECT_EQ(json["features"]["spread_px"], nlohmann::json({5, 8}));
}

TEST(TrainingProfileTest, PartialJsonKeepsDefaultsAndRangesMayBeObjects) {
  const nlohmann::json json = nlohmann::json::parse(R"({
    "depth_max_mm": 2000,
    "views": {"roll": {"min_deg": -30, "step_deg": 10, "max_deg": 30}},
    "features": {"color_features": 128}
  })");
  const TrainingProfile profile = TrainingProfileFromJson(json);
  EXPECT_EQ(profile.depth_min_mm, TrainingProfile().depth_min_mm);
  EXPECT_EQ(profile.depth_max_mm, 2000.0);
  EXPECT_EQ(profile.views.roll, (AngleRange{-30.0, 10.0, 30.0}));
  EXPECT_EQ(profile.views.elevation, TrainingProfile::DefaultEnvelopeViews().elevation);
  EXPECT_EQ(profile.features.color_features, 128);
  EXPECT_EQ(profile.features.normal_features, FeatureOptions().normal_features);
}

TEST(TrainingProfileTest, BadFieldsAreNamed) {
  const auto with = [](const std::string& pointer, const nlohmann::json& value) {
    nlohmann::json json = ToJson(TrainingProfile());
    json[nlohmann::json::json_pointer(pointer)] = value;
    return json;
  };
  ExpectFormatError(nlohmann::json::array(), "training profile is not a JSON object");
  ExpectFormatError(with("/depth_min_mm", "500"), "field 'depth_min_mm' must be a number");
  ExpectFormatError(with("/views", 3), "field 'views' is not a JSON object");
  ExpectFormatError(with("/views/azimuth", 15), "field 'views.azimuth' must be a \"min:step:max\"");
  ExpectFormatError(with("/views/azimuth", "0:15"), "field 'views.azimuth' is invalid");
  ExpectFormatError(with("/views/roll", "45:15:-45"), "field 'views.roll' is invalid");
  ExpectFormatError(with("/views/roll", nlohmann::json::parse(R"({"min_deg": 0, "max_deg": 9})")),
                    "field 'views.roll.step_deg' is missing");
  ExpectFormatError(with("/features/color_features", 63.5),
                    "field 'features.color_features' must be an integer");
  ExpectFormatError(with("/features/pyramid_levels", 1ll << 40),
                    "field 'features.pyramid_levels' must be within");
  ExpectFormatError(with("/features/weak_gradient", 1e300),
                    "field 'features.weak_gradient' is out of range");
  ExpectFormatError(with("/features/spread_px", nlohmann::json({5, "8"})),
                    "field 'features.spread_px' must be an array of small non-negative integers");
  ExpectFormatError(with("/features/colour_features", 63),
                    "field 'features.colour_features' is not a known field");
  ExpectFormatError(with("/depth_range", 1), "field 'depth_range' is not a known field");
}

TEST(TrainingProfileTest, InvalidValuesAreFormatErrors) {
  const auto with = [](const std::string& pointer, const nlohmann::json& value) {
    nlohmann::json json = ToJson(TrainingProfile());
    json[nlohmann::json::json_pointer(pointer)] = value;
    return json;
  };
  ExpectFormatError(with("/depth_min_mm", -5), "training profile: depth range");
  ExpectFormatError(with("/features/pyramid_levels", 3), "spread_px needs one value per");
  ExpectFormatError(with("/views/even_spacing_deg", 0.1), "even view spacing");
}

TEST(TrainingProfileTest, SaveAndLoadRoundTrip) {
  test::TempDir dir;
  SaveTrainingProfile(dir / "profile.json", Unusual());
  ExpectSameProfile(LoadTrainingProfile(dir / "profile.json"), Unusual());
  SaveTrainingProfile(dir / "profile.json", TrainingProfile());  // overwrite
  ExpectSameProfile(LoadTrainingProfile(dir / "profile.json"), TrainingProfile());
}

TEST(TrainingProfileTest, SaveRefusesInvalidProfilesAndMissingDirectories) {
  test::TempDir dir;
  TrainingProfile bad;
  bad.depth_max_mm = 100.0;
  EXPECT_THROW(SaveTrainingProfile(dir / "bad.json", bad), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.json"));
  EXPECT_THROW(SaveTrainingProfile(dir / "missing/p.json", TrainingProfile()), IoError);
}

TEST(TrainingProfileTest, LoadErrorsNameTheFile) {
  test::TempDir dir;
  EXPECT_THROW(LoadTrainingProfile(dir / "none.json"), IoError);
  WriteFileAtomically(dir / "broken.json", "{\"depth_min_mm\": ");
  try {
    LoadTrainingProfile(dir / "broken.json");
    FAIL() << "expected FormatError";
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find("broken.json': not valid JSON"), std::string::npos);
  }
  WriteFileAtomically(dir / "typed.json", R"({"features": {"min_features": "16"}})");
  try {
    LoadTrainingProfile(dir / "typed.json");
    FAIL() << "expected FormatError";
  } catch (const FormatError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("typed.json': training profile field 'features.min_features'"),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace layermod

namespace layermod {
namespace {

TEST(TrainingProfileUpAxisTest, NamedAxesAndRotationsRoundTrip) {
  TrainingProfile profile;
  profile.views.upright_from_model = UprightFromUpAxis("-z");
  nlohmann::json json = ToJson(profile);
  EXPECT_EQ(json["views"]["up_axis"], "-z");
  EXPECT_FALSE(json["views"].contains("upright_from_model"));
  ExpectSameProfile(TrainingProfileFromJson(json), profile);

  profile.views.upright_from_model =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  json = ToJson(profile);
  EXPECT_FALSE(json["views"].contains("up_axis"));
  EXPECT_EQ(json["views"]["upright_from_model"].size(), 9u);
  const TrainingProfile back = TrainingProfileFromJson(nlohmann::json::parse(json.dump()));
  EXPECT_TRUE(back.views.upright_from_model.isApprox(profile.views.upright_from_model, 1e-15));
  // Profiles and archives written before the up axis existed: +Z.
  json["views"].erase("upright_from_model");
  EXPECT_EQ(TrainingProfileFromJson(json).views.upright_from_model, Eigen::Matrix3d::Identity());
}

TEST(TrainingProfileUpAxisTest, BadOrientationsAreNamed) {
  ExpectFormatError({{"views", {{"up_axis", "up"}}}}, "'views.up_axis' must be one of");
  ExpectFormatError({{"views", {{"upright_from_model", {1, 0, 0, 0, 1, 0, 0, 0, -1}}}}},
                    "'views.upright_from_model' is not a rotation");
  ExpectFormatError({{"views", {{"upright_from_model", {1, 0, 0}}}}}, "must hold 9 numbers");
  ExpectFormatError(
      {{"views", {{"up_axis", "+z"}, {"upright_from_model", {1, 0, 0, 0, 1, 0, 0, 0, 1}}}}},
      "cannot both be given");
}

TEST(TrainingProfileUpAxisTest, PresetsKeepTheUpAxis) {
  const Eigen::Matrix3d up = UprightFromUpAxis("+y");
  const ViewSamplingOptions tabletop = ViewPreset("tabletop", up);
  const ViewSamplingOptions full = ViewPreset("full", up);
  EXPECT_EQ(tabletop.upright_from_model, up);
  EXPECT_EQ(full.upright_from_model, up);
  EXPECT_EQ(tabletop.roll, TrainingProfile::DefaultEnvelopeViews().roll);
  EXPECT_EQ(full.elevation.min_deg, -90.0);
  EXPECT_EQ(full.roll.Count(), 24u);
  // Twice the directions (the lower hemisphere too), 24 rolls instead of 7.
  EXPECT_EQ(CountViews(tabletop), 1001u);
  EXPECT_EQ(CountViews(full), 6864u);
  EXPECT_THROW(ViewPreset("sideways", up), Error);
}

}  // namespace
}  // namespace layermod
