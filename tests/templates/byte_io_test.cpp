// SPDX-License-Identifier: MIT
#include "templates/byte_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "features/feature.h"
#include "util/error.h"

namespace layermod {
namespace {

std::string Bytes(std::initializer_list<int> values) {
  std::string out;
  for (int value : values) out += static_cast<char>(value);
  return out;
}

TEST(ByteWriterTest, WritesLittleEndianWhateverTheHost) {
  std::string out;
  ByteWriter writer(out);
  writer.Put<std::uint32_t>(0x01020304u);
  writer.Put<std::int16_t>(-2);
  writer.Put<float>(1.0f);
  writer.Put<double>(-2.0);
  writer.Put(Modality::kDepthNormal);
  EXPECT_EQ(out, Bytes({0x04, 0x03, 0x02, 0x01,        // u32
                        0xFE, 0xFF,                    // i16 -2
                        0x00, 0x00, 0x80, 0x3F,        // 1.0f
                        0, 0, 0, 0, 0, 0, 0x00, 0xC0,  // -2.0
                        0x01}));                       // enum as u8
}

TEST(ByteReaderTest, ReadsBackEveryTypeExactly) {
  std::string out;
  ByteWriter writer(out);
  writer.Put<std::int64_t>(std::numeric_limits<std::int64_t>::min());
  writer.Put<std::uint64_t>(0xFEDCBA9876543210ull);
  writer.Put<std::int32_t>(-123456789);
  writer.Put<float>(0.1f);
  writer.Put<double>(std::numeric_limits<double>::denorm_min());
  writer.Put<double>(std::numeric_limits<double>::quiet_NaN());
  writer.Put<std::uint8_t>(255);
  ByteReader reader(out);
  EXPECT_EQ(reader.Get<std::int64_t>(), std::numeric_limits<std::int64_t>::min());
  EXPECT_EQ(reader.Get<std::uint64_t>(), 0xFEDCBA9876543210ull);
  EXPECT_EQ(reader.Get<std::int32_t>(), -123456789);
  EXPECT_EQ(reader.Get<float>(), 0.1f);
  EXPECT_EQ(reader.Get<double>(), std::numeric_limits<double>::denorm_min());
  EXPECT_TRUE(std::isnan(reader.Get<double>()));
  EXPECT_EQ(reader.Get<std::uint8_t>(), 255);
  EXPECT_EQ(reader.remaining(), 0u);
}

TEST(ByteReaderTest, ReadingPastTheEndIsAFormatError) {
  const std::string three = Bytes({1, 2, 3});
  ByteReader reader(three);
  EXPECT_EQ(reader.Get<std::uint16_t>(), 0x0201);
  EXPECT_THROW(reader.Get<std::uint16_t>(), FormatError);
  ByteReader beyond(three, 3);
  EXPECT_THROW(beyond.Get<std::uint8_t>(), FormatError);
}

TEST(ByteReaderTest, SkipZerosReportsNonZeroPadding) {
  const std::string padding = Bytes({0, 0, 0, 1});
  ByteReader reader(padding);
  EXPECT_TRUE(reader.SkipZeros(3));
  EXPECT_FALSE(reader.SkipZeros(1));
  EXPECT_THROW(reader.SkipZeros(1), FormatError);
}

}  // namespace
}  // namespace layermod
