// SPDX-License-Identifier: MIT
#include "render/clipping.h"

namespace layermod::render_internal {
namespace {

// Sutherland-Hodgman step: keeps the part of `input` where plane value >= 0.
ClipPolygon ClipByPlane(const ClipPolygon& input, int plane, const ScreenProjection& projection) {
  ClipPolygon output;
  std::array<float, ClipPolygon::kMaxVertices> values{};
  for (int i = 0; i < input.size; ++i) values[i] = projection.PlaneValue(plane, input.vertices[i]);
  for (int i = 0; i < input.size; ++i) {
    const int next = (i + 1) % input.size;
    const bool inside = values[i] >= 0.0f;
    const bool next_inside = values[next] >= 0.0f;
    if (inside) output.vertices[output.size++] = input.vertices[i];
    if (inside == next_inside) continue;
    const int in = inside ? i : next;
    const int out = inside ? next : i;
    const float t = values[in] / (values[in] - values[out]);
    output.vertices[output.size++] =
        input.vertices[in] + t * (input.vertices[out] - input.vertices[in]);
  }
  return output;
}

}  // namespace

ClipPolygon ClipTriangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                         const Eigen::Vector3f& c, std::uint32_t planes,
                         const ScreenProjection& projection) {
  ClipPolygon polygon;
  polygon.vertices[0] = a;
  polygon.vertices[1] = b;
  polygon.vertices[2] = c;
  polygon.size = 3;
  for (int plane = 0; plane < kClipPlaneCount && polygon.size >= 3; ++plane) {
    if ((planes & (1u << plane)) != 0) polygon = ClipByPlane(polygon, plane, projection);
  }
  if (polygon.size < 3) polygon.size = 0;
  return polygon;
}

}  // namespace layermod::render_internal
