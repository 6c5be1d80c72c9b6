// SPDX-License-Identifier: MIT
// Internal to the rasterizer: scan conversion of one screen-space triangle.
#pragma once

#include <algorithm>
#include <cstdint>

#include "render/screen_projection.h"

namespace layermod::render_internal {

// Inclusive range of image pixels to rasterize (the render window).
struct PixelWindow {
  int x0 = 0;
  int y0 = 0;
  int x1 = -1;
  int y1 = -1;

  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
  bool empty() const { return x1 < x0 || y1 < y0; }
};

// Fixed-point coordinate of the centre of image pixel `index` (column or row).
constexpr std::int64_t PixelCentreFixed(int index) {
  return static_cast<std::int64_t>(index + kGuardBandPx) * kSubpixelScale;
}

// Edge function of the directed edge a->b, stepped over pixel centres, multiplied by the
// triangle's orientation `sign` (+1 or -1) so that the inside is positive for either winding.
// It is offset so that "inside" is value >= 0 and a pixel centre exactly on the edge belongs to
// just one of the two triangles sharing the edge (the top-left rule: owned when the edge, in the
// triangle's positive orientation, goes up, or is horizontal going right).
struct EdgeFunction {
  std::int64_t value;   // at the current pixel centre
  std::int64_t step_x;  // per pixel to the right
  std::int64_t step_y;  // per pixel down

  EdgeFunction(const ScreenVertex& a, const ScreenVertex& b, std::int64_t sign, std::int64_t px,
               std::int64_t py) {
    const std::int64_t dx = sign * (static_cast<std::int64_t>(b.x) - a.x);
    const std::int64_t dy = sign * (static_cast<std::int64_t>(b.y) - a.y);
    // owned <=> key < 0, as |dx| < 2^23 inside the guard band; the sign bit gives the bias
    // without a branch, which would be mispredicted for every other triangle.
    const std::int64_t key = dy * (std::int64_t{1} << 25) - dx;
    value = dx * (py - a.y) - dy * (px - a.x) - 1 - (key >> 63);
    step_x = -dy * kSubpixelScale;
    step_y = dx * kSubpixelScale;
  }
};

// The pixels whose centres lie in a triangle's bounding box, clipped to `window`. Empty for many
// triangles of a dense mesh, which is why this test comes before any edge set-up.
inline PixelWindow TrianglePixelBox(const ScreenVertex& a, const ScreenVertex& b,
                                    const ScreenVertex& c, const PixelWindow& window) {
  constexpr int kRound = kSubpixelScale - 1;
  const int min_x = (std::min({a.x, b.x, c.x}) + kRound) >> kSubpixelBits;
  const int max_x = std::max({a.x, b.x, c.x}) >> kSubpixelBits;
  const int min_y = (std::min({a.y, b.y, c.y}) + kRound) >> kSubpixelBits;
  const int max_y = std::max({a.y, b.y, c.y}) >> kSubpixelBits;
  return {std::max(min_x - kGuardBandPx, window.x0), std::max(min_y - kGuardBandPx, window.y0),
          std::min(max_x - kGuardBandPx, window.x1), std::min(max_y - kGuardBandPx, window.y1)};
}

// Twice the signed area of triangle abc in fixed-point units. Negative for a triangle that is
// counter-clockwise seen from the camera's side (x right, y down): the front faces of a mesh with
// the usual outward counter-clockwise winding.
inline std::int64_t SignedArea(const ScreenVertex& a, const ScreenVertex& b,
                               const ScreenVertex& c) {
  return (static_cast<std::int64_t>(b.x) - a.x) * (static_cast<std::int64_t>(c.y) - a.y) -
         (static_cast<std::int64_t>(b.y) - a.y) * (static_cast<std::int64_t>(c.x) - a.x);
}

// Calls fragment(x, y, inv_z, inside) for every pixel centre of `box` (from TrianglePixelBox);
// `inside` tells whether the centre is inside triangle abc (either winding; degenerate triangles
// have none). Passing the test result instead of branching on it lets the caller update its
// buffers without a hard-to-predict branch: most boxes hold 1 to 4 pixels, half of them outside.
// inv_z is 1/z interpolated linearly in screen space, exact for the perspective image of a plane.
template <typename Fragment>
void RasterizeTriangleInBox(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                            const PixelWindow& box, Fragment&& fragment) {
  const std::int64_t signed_area = SignedArea(a, b, c);
  if (signed_area == 0) return;
  // Orientation without a branch: half the triangles of a view face away.
  const std::int64_t sign = (signed_area >> 63) | 1;
  const std::int64_t px = PixelCentreFixed(box.x0);
  const std::int64_t py = PixelCentreFixed(box.y0);
  EdgeFunction weight_a(b, c, sign, px, py);  // proportional to a's barycentric coordinate
  EdgeFunction weight_b(c, a, sign, px, py);
  EdgeFunction weight_c(a, b, sign, px, py);
  const float inv_area = 1.0f / static_cast<float>(sign * signed_area);
  const float dz_b = (b.inv_z - a.inv_z) * inv_area;
  const float dz_c = (c.inv_z - a.inv_z) * inv_area;

  // 1/z is evaluated exactly at the start of each row and stepped along it: the rounding that
  // accumulates over a row only matters between surfaces less than ~0.1 mm apart.
  const float dz_dx =
      static_cast<float>(weight_b.step_x) * dz_b + static_cast<float>(weight_c.step_x) * dz_c;
  for (int y = box.y0; y <= box.y1; ++y) {
    std::int64_t wa = weight_a.value;
    std::int64_t wb = weight_b.value;
    std::int64_t wc = weight_c.value;
    float inv_z = a.inv_z + static_cast<float>(wb) * dz_b + static_cast<float>(wc) * dz_c;
    for (int x = box.x0; x <= box.x1; ++x) {
      fragment(x, y, inv_z, (wa | wb | wc) >= 0);
      wa += weight_a.step_x;
      wb += weight_b.step_x;
      wc += weight_c.step_x;
      inv_z += dz_dx;
    }
    weight_a.value += weight_a.step_y;
    weight_b.value += weight_b.step_y;
    weight_c.value += weight_c.step_y;
  }
}

// RasterizeTriangleInBox for a box of one pixel (x, y), the commonest case in dense meshes, with
// the same arithmetic (so the same coverage) minus the stepping set-up.
template <typename Fragment>
inline void RasterizeTriangleAtPixel(const ScreenVertex& a, const ScreenVertex& b,
                                     const ScreenVertex& c, int x, int y, Fragment&& fragment) {
  const std::int64_t signed_area = SignedArea(a, b, c);
  if (signed_area == 0) return;
  const std::int64_t sign = (signed_area >> 63) | 1;
  const std::int64_t px = PixelCentreFixed(x);
  const std::int64_t py = PixelCentreFixed(y);
  const std::int64_t wa = EdgeFunction(b, c, sign, px, py).value;
  const std::int64_t wb = EdgeFunction(c, a, sign, px, py).value;
  const std::int64_t wc = EdgeFunction(a, b, sign, px, py).value;
  const float inv_area = 1.0f / static_cast<float>(sign * signed_area);
  const float dz_b = (b.inv_z - a.inv_z) * inv_area;
  const float dz_c = (c.inv_z - a.inv_z) * inv_area;
  fragment(x, y, a.inv_z + static_cast<float>(wb) * dz_b + static_cast<float>(wc) * dz_c,
           (wa | wb | wc) >= 0);
}

// Both steps for one triangle.
template <typename Fragment>
inline void RasterizeTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                              const PixelWindow& window, Fragment&& fragment) {
  const PixelWindow box = TrianglePixelBox(a, b, c, window);
  if (!box.empty()) RasterizeTriangleInBox(a, b, c, box, fragment);
}

}  // namespace layermod::render_internal
