// SPDX-License-Identifier: MIT
#include "match/simd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "util/error.h"

namespace layermod {
namespace {

constexpr std::uint8_t kGuard = 0xA5;

std::vector<std::uint8_t> RandomBuffer(int n, unsigned seed) {
  std::vector<std::uint8_t> buffer(n);
  unsigned state = seed;
  for (auto& value : buffer) {
    state = state * 1664525u + 1013904223u;
    value = static_cast<std::uint8_t>(state >> 24);
  }
  return buffer;
}

TEST(SimdTest, AutoResolvesToASupportedPathAndScalarAlwaysWorks) {
  const std::vector<SimdPath> paths = SupportedSimdPaths();
  ASSERT_FALSE(paths.empty());
  EXPECT_EQ(paths.front(), SimdPath::kScalar);
  EXPECT_NE(std::find(paths.begin(), paths.end(), ResolveSimdPath(SimdPath::kAuto)), paths.end());
  EXPECT_EQ(ResolveSimdPath(SimdPath::kScalar), SimdPath::kScalar);
  EXPECT_EQ(SimdPathName(SimdPath::kAvx2), "avx2");
}

TEST(SimdTest, RoundUpToBlock) {
  EXPECT_EQ(RoundUpToSimdBlock(0), 0);
  EXPECT_EQ(RoundUpToSimdBlock(1), kSimdBlock);
  EXPECT_EQ(RoundUpToSimdBlock(kSimdBlock), kSimdBlock);
  EXPECT_EQ(RoundUpToSimdBlock(kSimdBlock + 1), 2 * kSimdBlock);
}

TEST(SimdTest, AddRowsSaturateU8MatchesSequentialSaturatingSumsOnWholeBlocksOnly) {
  for (int count : {0, 1, 5, 70}) {
    for (int n : {1, 31, 32, 33, 127, 128, 129, 200, 257}) {
      const int blocks = RoundUpToSimdBlock(n);
      const std::ptrdiff_t offset = 3;
      std::vector<std::vector<std::uint8_t>> rows;
      std::vector<const std::uint8_t*> sources;
      rows.reserve(count);
      sources.reserve(count);
      for (int s = 0; s < count; ++s) rows.push_back(RandomBuffer(blocks + 3, 10 + s));
      for (const auto& row : rows) sources.push_back(row.data());
      std::vector<std::uint8_t> initial = RandomBuffer(blocks + 8, 2);
      std::fill(initial.begin() + blocks, initial.end(), kGuard);
      for (int i = 0; i < blocks; ++i) initial[i] /= 4;  // some sums stay below saturation
      for (SimdPath path : SupportedSimdPaths()) {
        std::vector<std::uint8_t> acc = initial;
        AddRowsSaturateU8(acc.data(), sources.data(), count, offset, n, path);
        for (int i = 0; i < blocks; ++i) {
          int expected = initial[i];
          for (int s = 0; s < count; ++s) expected = std::min(expected + rows[s][offset + i], 255);
          ASSERT_EQ(acc[i], expected) << SimdPathName(path) << " n=" << n << " i=" << i;
        }
        for (int i = blocks; i < blocks + 8; ++i) ASSERT_EQ(acc[i], kGuard) << SimdPathName(path);
      }
    }
  }
}

TEST(SimdTest, AddSaturateWidenU16MatchesDefinitionIncludingSaturation) {
  for (int n : {1, 16, 32, 33, 200}) {
    const int blocks = RoundUpToSimdBlock(n);
    const std::vector<std::uint8_t> src = RandomBuffer(blocks, 3);
    std::vector<std::uint16_t> initial(blocks + 4, 0xBEEF);
    for (int i = 0; i < blocks; ++i) initial[i] = static_cast<std::uint16_t>(65400 + i % 200);
    for (SimdPath path : SupportedSimdPaths()) {
      std::vector<std::uint16_t> acc = initial;
      AddSaturateWidenU16(acc.data(), src.data(), n, path);
      for (int i = 0; i < blocks; ++i) {
        ASSERT_EQ(acc[i], std::min(initial[i] + src[i], 65535)) << SimdPathName(path) << " " << i;
      }
      for (int i = blocks; i < blocks + 4; ++i) ASSERT_EQ(acc[i], 0xBEEF) << SimdPathName(path);
    }
  }
}

TEST(SimdTest, LookupNibbleMaxIsExactInLength) {
  const std::vector<std::uint8_t> low = RandomBuffer(16, 4);
  const std::vector<std::uint8_t> high = RandomBuffer(16, 5);
  for (int n : {0, 1, 15, 16, 17, 31, 32, 33, 95}) {
    const std::vector<std::uint8_t> src = RandomBuffer(n + 1, 6);
    for (SimdPath path : SupportedSimdPaths()) {
      std::vector<std::uint8_t> dst(n + 8, kGuard);
      LookupNibbleMax(src.data(), dst.data(), n, low.data(), high.data(), path);
      for (int i = 0; i < n; ++i) {
        ASSERT_EQ(dst[i], std::max(low[src[i] & 15], high[src[i] >> 4])) << SimdPathName(path);
      }
      for (int i = n; i < n + 8; ++i) ASSERT_EQ(dst[i], kGuard) << SimdPathName(path);
    }
  }
}

}  // namespace
}  // namespace layermod
