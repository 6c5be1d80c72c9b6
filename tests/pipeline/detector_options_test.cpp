// SPDX-License-Identifier: MIT
#include "pipeline/detector_options.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "support/thrown.h"
#include "util/error.h"

namespace layermod {
namespace {

TEST(DetectorOptionsTest, JsonRoundTripKeepsEveryField) {
  DetectorOptions options;
  options.mode = DetectionMode::kExhaustive;
  options.match.search = TemplateSearchMode::kFlat;
  options.match.threshold_percent = 81.5f;
  options.coarse.max_blocks = 3;
  options.icp.max_drift_deg = 12.0;
  options.verification.min_color_agreement = 0.25;
  const nlohmann::json json = DetectorOptionsToJson(options);
  EXPECT_EQ(json.at("mode"), "exhaustive");
  EXPECT_EQ(json.size(), DetectorOptionFields().size());

  const DetectorOptions back = DetectorOptionsFromJson(json, "test");
  EXPECT_EQ(DetectorOptionsToJson(back), json);
  EXPECT_EQ(back.mode, DetectionMode::kExhaustive);
  EXPECT_EQ(json.at("search"), "flat");
  EXPECT_EQ(back.match.search, TemplateSearchMode::kFlat);
  EXPECT_FLOAT_EQ(back.match.threshold_percent, 81.5f);
  EXPECT_EQ(back.coarse.max_blocks, 3);
}

TEST(DetectorOptionsTest, FieldsHaveUniqueKeysAndDefaultsInsideTheirRange) {
  std::set<std::string_view> keys;
  const nlohmann::json defaults = DetectorOptionsToJson(DetectorOptions{});
  for (const DetectorOptionField& field : DetectorOptionFields()) {
    EXPECT_TRUE(keys.insert(field.key).second) << field.key;
    EXPECT_FALSE(field.help.empty()) << field.key;
    const nlohmann::json& value = defaults.at(std::string(field.key));
    if (value.is_number()) {
      EXPECT_GE(value.get<double>(), field.min) << field.key;
      EXPECT_LE(value.get<double>(), field.max) << field.key;
    }
  }
}

TEST(DetectorOptionsTest, AbsentFieldsKeepTheBase) {
  DetectorOptions base;
  base.max_instances = 4;
  const DetectorOptions merged =
      DetectorOptionsFromJson(nlohmann::json{{"threshold", 75}}, "test", base);
  EXPECT_EQ(merged.max_instances, 4);
  EXPECT_FLOAT_EQ(merged.match.threshold_percent, 75.0f);
}

TEST(DetectorOptionsTest, FlagsFollowTheKeys) {
  EXPECT_EQ(OptionFlag(DetectorOptionField{"edge_upper", "", "", 0, 1}), "--edge-upper");
  EXPECT_EQ(FormatRange(100.0), "100");
  EXPECT_EQ(FormatRange(0.5), "0.5");
}

TEST(DetectorOptionsTest, BadValuesNameTheField) {
  auto read = [](const nlohmann::json& json) {
    return test::ThrownMessage<FormatError>([&] { DetectorOptionsFromJson(json, "profile"); });
  };
  EXPECT_EQ(read({{"threshold", 120}}), "profile field 'threshold' must lie in [1, 100]");
  EXPECT_EQ(read({{"instances", 1.5}}), "profile field 'instances' must be an integer");
  EXPECT_EQ(read({{"min_confidence", 1.2}}), "profile field 'min_confidence' must lie in [0, 1]");
  EXPECT_EQ(read({{"min_confidence", -0.1}}), "profile field 'min_confidence' must lie in [0, 1]");
  EXPECT_EQ(read({{"threshold", "high"}}), "profile field 'threshold' must be a number");
  EXPECT_NE(read({{"mode", "psychic"}}).find("profile field 'mode'"), std::string::npos);
  EXPECT_EQ(read({{"search", "deep"}}),
            "profile field 'search': search: expected tree or flat, got 'deep'");
  EXPECT_EQ(read({{"search", 1}}), "profile field 'search' must be a string");
  EXPECT_EQ(read({{"thresold", 70}}), "profile: unknown detector setting 'thresold'");
  EXPECT_EQ(read(nlohmann::json::array()), "profile is not a JSON object");
  // Each value in range, together inconsistent: the options' own validation speaks.
  EXPECT_NE(read({{"edge_lower", 3}, {"edge_upper", 2}}).find("lower factor <= upper factor"),
            std::string::npos);
}

TEST(DetectorOptionsTest, ProfileFileRoundTripAndErrorsNameTheFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "layermod_profile";
  std::filesystem::create_directories(dir);
  DetectorOptions options;
  options.pose_candidates = 7;
  options.mode = DetectionMode::kColorOnly;
  WriteDetectorProfile(dir / "a.json", options);
  const DetectorOptions back = ReadDetectorProfile(dir / "a.json");
  EXPECT_EQ(back.pose_candidates, 7);
  EXPECT_EQ(back.mode, DetectionMode::kColorOnly);

  std::ofstream(dir / "bad.json") << "{ not json";
  EXPECT_NE(test::ThrownMessage<FormatError>([&] {
              ReadDetectorProfile(dir / "bad.json");
            }).find("bad.json"),
            std::string::npos);
  EXPECT_NE(test::ThrownMessage<IoError>([&] {
              ReadDetectorProfile(dir / "missing.json");
            }).find("missing.json"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace layermod
