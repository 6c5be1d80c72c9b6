// SPDX-License-Identifier: MIT
// The few byte kernels the LineMOD matcher spends its time in, with a scalar path and x86 SIMD
// paths chosen at run time. The baseline build is plain x86-64 (SSE2); the SSSE3 and AVX2 paths
// are compiled with target attributes and only called when the CPU reports them, so one binary
// runs everywhere and still uses the wide instructions where they exist.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace layermod {

enum class SimdPath {
  kAuto,    // the best path the CPU supports
  kScalar,  // portable C++
  kSse,     // SSE2 additions, SSSE3 byte shuffles (needs SSSE3)
  kAvx2,    // AVX2
};

// kAuto -> the best supported path; any other path is returned when the CPU supports it, else
// Error is thrown (tests and benchmarks force paths; production code passes kAuto).
SimdPath ResolveSimdPath(SimdPath requested);
// The paths this CPU can run, kScalar first.
std::vector<SimdPath> SupportedSimdPaths();
std::string_view SimdPathName(SimdPath path);

// The accumulation kernels work on whole blocks of kSimdBlock elements in every path: they
// process RoundUpToSimdBlock(n) elements, so both buffers must be addressable that far. Callers
// keep kSimdBlock elements of slack after their rows instead of paying for scalar tails.
inline constexpr int kSimdBlock = 32;
constexpr int RoundUpToSimdBlock(int n) { return (n + kSimdBlock - 1) / kSimdBlock * kSimdBlock; }

// For i < RoundUpToSimdBlock(n): acc[i] plus sources[s][offset + i] for s = 0..count-1, each
// addition saturating at 255 (the same in every path). Works on tiles of consecutive elements
// held in registers while all sources are added, so the accumulator is not reloaded per source.
// `path` must be resolved.
void AddRowsSaturateU8(std::uint8_t* acc, const std::uint8_t* const* sources, int count,
                       std::ptrdiff_t offset, int n, SimdPath path);

// acc[i] = min(acc[i] + src[i], 65535) for i < RoundUpToSimdBlock(n). `path` must be resolved.
void AddSaturateWidenU16(std::uint16_t* acc, const std::uint8_t* src, int n, SimdPath path);

// dst[i] = max(lut_low[src[i] & 15], lut_high[src[i] >> 4]) for exactly i < n (two 16-entry
// tables, one per nibble). `path` must be resolved.
void LookupNibbleMax(const std::uint8_t* src, std::uint8_t* dst, int n, const std::uint8_t* lut_low,
                     const std::uint8_t* lut_high, SimdPath path);

}  // namespace layermod
