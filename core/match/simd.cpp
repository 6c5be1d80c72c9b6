// SPDX-License-Identifier: MIT
#include "match/simd.h"

#include <algorithm>
#include <array>
#include <string>

#include "util/error.h"

#if defined(__x86_64__) || defined(__i386__)
#define LAYERMOD_MATCH_X86 1
#include <immintrin.h>
#endif

namespace layermod {
namespace {

// ---- Scalar ----------------------------------------------------------------------------------

void AddRowsSaturateU8Scalar(std::uint8_t* acc, const std::uint8_t* const* sources, int count,
                             std::ptrdiff_t offset, int n) {
  const int blocks = RoundUpToSimdBlock(n);
  // Source by source over a local copy of one block: independent additions the compiler can
  // vectorize without aliasing checks (the tile cannot alias a source).
  std::array<std::uint8_t, kSimdBlock> tile{};
  for (int i = 0; i < blocks; i += kSimdBlock) {
    std::copy_n(acc + i, kSimdBlock, tile.begin());
    for (int s = 0; s < count; ++s) {
      const std::uint8_t* src = sources[s] + offset + i;
      for (int j = 0; j < kSimdBlock; ++j) {
        const int sum = tile[j] + src[j];
        tile[j] = static_cast<std::uint8_t>(sum > 255 ? 255 : sum);
      }
    }
    std::copy_n(tile.begin(), kSimdBlock, acc + i);
  }
}

void AddSaturateWidenU16Scalar(std::uint16_t* acc, const std::uint8_t* src, int n) {
  const int blocks = RoundUpToSimdBlock(n);
  for (int i = 0; i < blocks; ++i) {
    acc[i] = static_cast<std::uint16_t>(std::min(acc[i] + src[i], 65535));
  }
}

void LookupNibbleMaxScalar(const std::uint8_t* src, std::uint8_t* dst, int n,
                           const std::uint8_t* lut_low, const std::uint8_t* lut_high) {
  for (int i = 0; i < n; ++i) {
    dst[i] = std::max(lut_low[src[i] & 15], lut_high[src[i] >> 4]);
  }
}

#if LAYERMOD_MATCH_X86

// ---- SSE2 / SSSE3 ----------------------------------------------------------------------------

__m128i Load128(const void* p) { return _mm_loadu_si128(static_cast<const __m128i*>(p)); }
void Store128(void* p, __m128i v) { _mm_storeu_si128(static_cast<__m128i*>(p), v); }

// Tiles of kTileVectors registers: enough to hide load latency, few enough for the register file.
constexpr int kTileVectors = 4;

void AddRowsSaturateU8Sse(std::uint8_t* acc, const std::uint8_t* const* sources, int count,
                          std::ptrdiff_t offset, int n) {
  const int blocks = RoundUpToSimdBlock(n);
  int i = 0;
  for (; i + 16 * kTileVectors <= blocks; i += 16 * kTileVectors) {
    __m128i a0 = Load128(acc + i), a1 = Load128(acc + i + 16);
    __m128i a2 = Load128(acc + i + 32), a3 = Load128(acc + i + 48);
    for (int s = 0; s < count; ++s) {
      const std::uint8_t* src = sources[s] + offset + i;
      a0 = _mm_adds_epu8(a0, Load128(src));
      a1 = _mm_adds_epu8(a1, Load128(src + 16));
      a2 = _mm_adds_epu8(a2, Load128(src + 32));
      a3 = _mm_adds_epu8(a3, Load128(src + 48));
    }
    Store128(acc + i, a0);
    Store128(acc + i + 16, a1);
    Store128(acc + i + 32, a2);
    Store128(acc + i + 48, a3);
  }
  for (; i < blocks; i += 16) {
    __m128i a = Load128(acc + i);
    for (int s = 0; s < count; ++s) a = _mm_adds_epu8(a, Load128(sources[s] + offset + i));
    Store128(acc + i, a);
  }
}

void AddSaturateWidenU16Sse(std::uint16_t* acc, const std::uint8_t* src, int n) {
  const int blocks = RoundUpToSimdBlock(n);
  const __m128i zero = _mm_setzero_si128();
  for (int i = 0; i < blocks; i += 16) {
    const __m128i bytes = Load128(src + i);
    Store128(acc + i, _mm_adds_epu16(Load128(acc + i), _mm_unpacklo_epi8(bytes, zero)));
    Store128(acc + i + 8, _mm_adds_epu16(Load128(acc + i + 8), _mm_unpackhi_epi8(bytes, zero)));
  }
}

__attribute__((target("ssse3"))) void LookupNibbleMaxSsse3(const std::uint8_t* src,
                                                           std::uint8_t* dst, int n,
                                                           const std::uint8_t* lut_low,
                                                           const std::uint8_t* lut_high) {
  const __m128i low_table = Load128(lut_low);
  const __m128i high_table = Load128(lut_high);
  const __m128i nibble = _mm_set1_epi8(0x0F);
  int i = 0;
  for (; i + 16 <= n; i += 16) {
    const __m128i v = Load128(src + i);
    const __m128i low = _mm_shuffle_epi8(low_table, _mm_and_si128(v, nibble));
    const __m128i high = _mm_shuffle_epi8(high_table, _mm_and_si128(_mm_srli_epi16(v, 4), nibble));
    Store128(dst + i, _mm_max_epu8(low, high));
  }
  LookupNibbleMaxScalar(src + i, dst + i, n - i, lut_low, lut_high);
}

// ---- AVX2 ------------------------------------------------------------------------------------

__attribute__((target("avx2"))) __m256i Load256(const void* p) {
  return _mm256_loadu_si256(static_cast<const __m256i*>(p));
}
__attribute__((target("avx2"))) void Store256(void* p, __m256i v) {
  _mm256_storeu_si256(static_cast<__m256i*>(p), v);
}

__attribute__((target("avx2"))) void AddRowsSaturateU8Avx2(std::uint8_t* acc,
                                                           const std::uint8_t* const* sources,
                                                           int count, std::ptrdiff_t offset,
                                                           int n) {
  const int blocks = RoundUpToSimdBlock(n);
  int i = 0;
  for (; i + 32 * kTileVectors <= blocks; i += 32 * kTileVectors) {
    __m256i a0 = Load256(acc + i), a1 = Load256(acc + i + 32);
    __m256i a2 = Load256(acc + i + 64), a3 = Load256(acc + i + 96);
    for (int s = 0; s < count; ++s) {
      const std::uint8_t* src = sources[s] + offset + i;
      a0 = _mm256_adds_epu8(a0, Load256(src));
      a1 = _mm256_adds_epu8(a1, Load256(src + 32));
      a2 = _mm256_adds_epu8(a2, Load256(src + 64));
      a3 = _mm256_adds_epu8(a3, Load256(src + 96));
    }
    Store256(acc + i, a0);
    Store256(acc + i + 32, a1);
    Store256(acc + i + 64, a2);
    Store256(acc + i + 96, a3);
  }
  for (; i < blocks; i += 32) {
    __m256i a = Load256(acc + i);
    for (int s = 0; s < count; ++s) a = _mm256_adds_epu8(a, Load256(sources[s] + offset + i));
    Store256(acc + i, a);
  }
}

__attribute__((target("avx2"))) void AddSaturateWidenU16Avx2(std::uint16_t* acc,
                                                             const std::uint8_t* src, int n) {
  const int blocks = RoundUpToSimdBlock(n);
  for (int i = 0; i < blocks; i += 16) {
    const __m256i words = _mm256_cvtepu8_epi16(Load128(src + i));
    Store256(acc + i, _mm256_adds_epu16(Load256(acc + i), words));
  }
}

__attribute__((target("avx2"))) void LookupNibbleMaxAvx2(const std::uint8_t* src, std::uint8_t* dst,
                                                         int n, const std::uint8_t* lut_low,
                                                         const std::uint8_t* lut_high) {
  // vpshufb looks up within each 128-bit lane, so both lanes hold the same table.
  const __m256i low_table = _mm256_broadcastsi128_si256(Load128(lut_low));
  const __m256i high_table = _mm256_broadcastsi128_si256(Load128(lut_high));
  const __m256i nibble = _mm256_set1_epi8(0x0F);
  int i = 0;
  for (; i + 32 <= n; i += 32) {
    const __m256i v = Load256(src + i);
    const __m256i low = _mm256_shuffle_epi8(low_table, _mm256_and_si256(v, nibble));
    const __m256i high =
        _mm256_shuffle_epi8(high_table, _mm256_and_si256(_mm256_srli_epi16(v, 4), nibble));
    Store256(dst + i, _mm256_max_epu8(low, high));
  }
  LookupNibbleMaxScalar(src + i, dst + i, n - i, lut_low, lut_high);
}

#endif  // LAYERMOD_MATCH_X86

bool Supported(SimdPath path) {
  switch (path) {
    case SimdPath::kAuto:
    case SimdPath::kScalar:
      return true;
#if LAYERMOD_MATCH_X86
    case SimdPath::kSse:
      return __builtin_cpu_supports("ssse3");
    case SimdPath::kAvx2:
      // GCC's check includes the OS's XSAVE support of the AVX state.
      return __builtin_cpu_supports("avx2");
#else
    case SimdPath::kSse:
    case SimdPath::kAvx2:
      return false;
#endif
  }
  return false;
}

SimdPath DetectBestPath() {
#if LAYERMOD_MATCH_X86
  __builtin_cpu_init();
#endif
  if (Supported(SimdPath::kAvx2)) return SimdPath::kAvx2;
  if (Supported(SimdPath::kSse)) return SimdPath::kSse;
  return SimdPath::kScalar;
}

}  // namespace

SimdPath ResolveSimdPath(SimdPath requested) {
  static const SimdPath best = DetectBestPath();
  if (requested == SimdPath::kAuto) return best;
  if (!Supported(requested)) {
    throw Error("SIMD path '" + std::string(SimdPathName(requested)) +
                "' is not supported by this CPU");
  }
  return requested;
}

std::vector<SimdPath> SupportedSimdPaths() {
  std::vector<SimdPath> paths;
  for (SimdPath path : {SimdPath::kScalar, SimdPath::kSse, SimdPath::kAvx2}) {
    if (Supported(path)) paths.push_back(path);
  }
  return paths;
}

std::string_view SimdPathName(SimdPath path) {
  switch (path) {
    case SimdPath::kAuto:
      return "auto";
    case SimdPath::kScalar:
      return "scalar";
    case SimdPath::kSse:
      return "sse";
    case SimdPath::kAvx2:
      return "avx2";
  }
  return "unknown";
}

void AddRowsSaturateU8(std::uint8_t* acc, const std::uint8_t* const* sources, int count,
                       std::ptrdiff_t offset, int n, SimdPath path) {
#if LAYERMOD_MATCH_X86
  if (path == SimdPath::kAvx2) return AddRowsSaturateU8Avx2(acc, sources, count, offset, n);
  if (path == SimdPath::kSse) return AddRowsSaturateU8Sse(acc, sources, count, offset, n);
#endif
  (void)path;
  AddRowsSaturateU8Scalar(acc, sources, count, offset, n);
}

void AddSaturateWidenU16(std::uint16_t* acc, const std::uint8_t* src, int n, SimdPath path) {
#if LAYERMOD_MATCH_X86
  if (path == SimdPath::kAvx2) return AddSaturateWidenU16Avx2(acc, src, n);
  if (path == SimdPath::kSse) return AddSaturateWidenU16Sse(acc, src, n);
#endif
  (void)path;
  AddSaturateWidenU16Scalar(acc, src, n);
}

void LookupNibbleMax(const std::uint8_t* src, std::uint8_t* dst, int n, const std::uint8_t* lut_low,
                     const std::uint8_t* lut_high, SimdPath path) {
#if LAYERMOD_MATCH_X86
  if (path == SimdPath::kAvx2) return LookupNibbleMaxAvx2(src, dst, n, lut_low, lut_high);
  if (path == SimdPath::kSse) return LookupNibbleMaxSsse3(src, dst, n, lut_low, lut_high);
#endif
  (void)path;
  LookupNibbleMaxScalar(src, dst, n, lut_low, lut_high);
}

}  // namespace layermod
