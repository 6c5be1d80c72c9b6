// SPDX-License-Identifier: MIT
// Internal to the rasterizer: camera-space points to fixed-point screen coordinates.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/camera.h"

namespace layermod::render_internal {

// Vertices are snapped to 1/256 px so edge functions are exact integers: a pixel centre on an
// edge shared by two triangles is then decided identically for both (no gaps, no double hits).
inline constexpr int kSubpixelBits = 8;
inline constexpr int kSubpixelScale = 1 << kSubpixelBits;
// Triangles are clipped to a guard band this far outside the image. It bounds the fixed-point
// coordinates (edge functions fit in 64 bits) and keeps clip edges far from every pixel centre.
inline constexpr int kGuardBandPx = 1024;
// Fixed-point coordinates stay below 2^23 for any valid camera (PinholeCamera::Validate allows up
// to 16384 pixels a side), which the edge functions rely on.
inline constexpr int kMaxImageSidePx = 16384;
static_assert((kMaxImageSidePx + 2 * kGuardBandPx) * kSubpixelScale < (1 << 23));

// One bit per clip plane a camera-space point lies outside of; kInvalid marks non-finite input.
enum ClipBit : std::uint32_t {
  kBehindNear = 1u << 0,
  kOutsideLeft = 1u << 1,
  kOutsideRight = 1u << 2,
  kOutsideTop = 1u << 3,
  kOutsideBottom = 1u << 4,
  kInvalid = 1u << 5,
};
inline constexpr int kClipPlaneCount = 5;
inline constexpr std::uint32_t kAllClipPlanes = (1u << kClipPlaneCount) - 1;

// A projected vertex. x, y are fixed point with the origin at image pixel
// (-kGuardBandPx, -kGuardBandPx), clamped to [0, 2^23); they are exact only when outcode == 0
// (in front of the near plane and inside the guard band), as is inv_z. No default member values:
// per-view arrays of these are allocated without initialisation.
struct ScreenVertex {
  std::int32_t x;
  std::int32_t y;
  float inv_z;
  std::uint32_t outcode;
};

// The camera's projection and clip planes in float, shared by the per-vertex pass and the
// clipper so a vertex projects to the same bits on both paths.
class ScreenProjection {
 public:
  ScreenProjection(const PinholeCamera& camera, float near_mm);

  float near_mm() const { return near_mm_; }
  // Plane value of `point` for clip plane `plane` (index of its ClipBit): >= 0 inside.
  float PlaneValue(int plane, const Eigen::Vector3f& point) const {
    const Eigen::Vector4f& p = planes_[plane];
    return p.x() * point.x() + p.y() * point.y() + p.z() * point.z() + p.w();
  }
  // Writes the screen vertex (with outcode) of one camera-space point. Fields are written one by
  // one: building a struct and copying it stalls store forwarding in the per-vertex loop.
  void ProjectVertex(const Eigen::Vector3f& point, ScreenVertex& screen) const {
    const float inv_z = 1.0f / point.z();
    const float u = fx_ * point.x() * inv_z + cx_;  // image coordinates, pixel centres at integers
    const float v = fy_ * point.y() * inv_z + cy_;
    screen.x = ToFixed(u);
    screen.y = ToFixed(v);
    screen.inv_z = inv_z;
    screen.outcode = Outcode(point, u, v);
  }
  // Fixed-point vertex of a finite point produced by clipping (on or inside every clip plane).
  ScreenVertex Project(Eigen::Vector3f point) const {
    point.z() = std::max(point.z(), near_mm_);  // clipped points may round just below near
    ScreenVertex screen;
    ProjectVertex(point, screen);
    screen.outcode = 0;
    return screen;
  }

 private:
  // Side bits are left out behind the near plane, where the projection mirrors; the clipper
  // then uses every plane, so no bit is needed there.
  std::uint32_t Outcode(const Eigen::Vector3f& point, float u, float v) const {
    constexpr float kMax = std::numeric_limits<float>::max();
    // Arithmetic on comparison results rather than branches: the per-vertex loop stays branch-free.
    const auto bit = [](bool value) { return static_cast<std::uint32_t>(value); };
    const std::uint32_t finite = bit(std::abs(point.x()) <= kMax) &
                                 bit(std::abs(point.y()) <= kMax) &
                                 bit(std::abs(point.z()) <= kMax);
    const std::uint32_t in_front = point.z() > near_mm_;
    const std::uint32_t sides = kOutsideLeft * (u < -guard_) | kOutsideRight * (u > right_) |
                                kOutsideTop * (v < -guard_) | kOutsideBottom * (v > bottom_);
    return kInvalid * (1u - finite) | finite * (kBehindNear * (1u - in_front) | in_front * sides);
  }
  // Fixed point with the origin at pixel (-guard, -guard). The clamp keeps the conversion
  // defined (NaN goes to 0); it never acts on a vertex inside the guard band.
  std::int32_t ToFixed(float image_coordinate) const {
    const float fixed = image_coordinate * static_cast<float>(kSubpixelScale) + fixed_offset_;
    return static_cast<std::int32_t>(std::max(0.0f, std::min(fixed, max_fixed_)));
  }

  float fx_, fy_, cx_, cy_;
  float near_mm_;
  float guard_;           // guard band width in pixels
  float right_, bottom_;  // last column/row inside the guard band
  float fixed_offset_;    // guard * scale + 0.5: truncation then rounds to nearest
  float max_fixed_;
  std::array<Eigen::Vector4f, kClipPlaneCount> planes_;
};

}  // namespace layermod::render_internal
