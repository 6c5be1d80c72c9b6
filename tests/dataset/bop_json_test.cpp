// SPDX-License-Identifier: MIT
#include "dataset/bop_json.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "util/error.h"

namespace layermod::bop_internal {
namespace {

using ::testing::HasSubstr;

const JsonContext kContext{"/data/scene_gt.json", "image 3"};

std::string FailureOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const FormatError& error) {
    return error.what();
  }
  return "";
}

TEST(BopJsonTest, IdKeysAreNonNegativeIntegers) {
  EXPECT_EQ(ParseIdKey("42", kContext), 42);
  EXPECT_EQ(ParseIdKey("000007", kContext), 7);
  for (const char* bad : {"", "-1", "4a", "1.5", "99999999999"}) {
    EXPECT_THROW(ParseIdKey(bad, kContext), FormatError) << bad;
  }
}

TEST(BopJsonTest, MessagesNameTheFilePlaceAndField) {
  const nlohmann::json entry = {{"obj_id", "seven"}, {"t", {1, 2}}};
  EXPECT_EQ(FailureOf([&] { IntField(entry, "obj_id", kContext); }),
            "'/data/scene_gt.json': image 3: 'obj_id' must be an integer");
  EXPECT_THAT(FailureOf([&] { NumbersField(entry, "t", 3, kContext.Inside("instance 1")); }),
              HasSubstr("image 3, instance 1: 't' must be 3 numbers"));
  EXPECT_THAT(FailureOf([&] { NumberField(entry, "missing", kContext); }),
              HasSubstr("'missing' is missing"));
}

TEST(BopJsonTest, PosesAreRowMajor) {
  const nlohmann::json entry = {{"R", {0, -1, 0, 1, 0, 0, 0, 0, 1}}, {"t", {1, 2, 3}}};
  const Pose pose = PoseFields(entry, "R", "t", kContext);
  EXPECT_EQ(pose.R(0, 1), -1.0);
  EXPECT_EQ(pose.R(1, 0), 1.0);
  EXPECT_EQ(pose.t, Eigen::Vector3d(1, 2, 3));
  const Pose back = PoseFrom4x4(PoseTo4x4(pose));
  EXPECT_EQ(back.R, pose.R);
  EXPECT_EQ(back.t, pose.t);
  EXPECT_EQ(PoseTo4x4(pose)[15], 1.0);
}

}  // namespace
}  // namespace layermod::bop_internal
