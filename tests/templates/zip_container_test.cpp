// SPDX-License-Identifier: MIT
#include "templates/zip_container.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace layermod {
namespace {

std::string Sample() {
  std::string big;
  for (int i = 0; i < 100000; ++i) big += static_cast<char>('a' + i * 7 % 13);
  return WriteZip({{"first.txt", "stored text", false}, {"big.bin", big, true}});
}

TEST(ZipContainerTest, RoundTripKeepsOrderNamesAndCompression) {
  const std::string bytes = Sample();
  const ZipReader zip(bytes);
  ASSERT_EQ(zip.EntryCount(), 2u);
  EXPECT_EQ(zip.Entry(0).name, "first.txt");
  EXPECT_TRUE(zip.Entry(0).stored);
  EXPECT_FALSE(zip.Entry(1).stored);
  EXPECT_LT(zip.Entry(1).compressed_size, zip.Entry(1).size);
  EXPECT_EQ(zip.Read(0, 100), "stored text");
  EXPECT_EQ(zip.Read(*zip.Find("big.bin"), 100000).size(), 100000u);
  EXPECT_FALSE(zip.Find("nothing").has_value());
}

TEST(ZipContainerTest, SameEntriesGiveSameBytes) { EXPECT_EQ(Sample(), Sample()); }

TEST(ZipContainerTest, EntryLargerThanAllowedIsRefused) {
  const std::string bytes = Sample();
  const ZipReader zip(bytes);
  EXPECT_THROW(zip.Read(1, 99999), FormatError);
}

TEST(ZipContainerTest, TruncatedContainerIsAFormatError) {
  const std::string bytes = Sample();
  EXPECT_THROW(ZipReader(std::string_view(bytes).substr(0, bytes.size() - 10)), FormatError);
  EXPECT_THROW(ZipReader(std::string_view(bytes).substr(0, 30)), FormatError);
}

TEST(ZipContainerTest, DamagedStoredEntryFailsItsChecksum) {
  std::string bytes = Sample();
  const std::size_t at = bytes.find("stored text");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'S';
  const ZipReader zip(bytes);
  try {
    zip.Read(0, 100);
    FAIL() << "expected a CRC error";
  } catch (const FormatError& error) {
    EXPECT_NE(std::string(error.what()).find("first.txt"), std::string::npos) << error.what();
  }
}

TEST(ZipContainerTest, DamagedDeflatedEntryIsAFormatError) {
  const std::string good = Sample();
  const ZipReader probe(good);
  const std::size_t data_start = good.find("big.bin") + 7;  // local header name, then data
  int rejected = 0;
  for (std::size_t offset = data_start; offset < data_start + probe.Entry(1).compressed_size;
       ++offset) {
    std::string bytes = good;
    bytes[offset] = static_cast<char>(bytes[offset] ^ 0x55);
    try {
      const ZipReader zip(bytes);
      zip.Read(1, 100000);
    } catch (const FormatError&) {
      ++rejected;
    }
  }
  // Every flip in the compressed data changes the output or breaks the stream.
  EXPECT_EQ(rejected, static_cast<int>(probe.Entry(1).compressed_size));
}

}  // namespace
}  // namespace layermod
