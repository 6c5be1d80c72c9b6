// SPDX-License-Identifier: MIT
#include "render/visibility.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <limits>

#include "render/clipping.h"

namespace layermod::render_internal {
namespace {

constexpr std::uint32_t kNotInFront = kBehindNear | kInvalid;

// Bounding box of fixed-point screen coordinates.
struct FixedBounds {
  std::int32_t min_x = std::numeric_limits<std::int32_t>::max();
  std::int32_t min_y = std::numeric_limits<std::int32_t>::max();
  std::int32_t max_x = std::numeric_limits<std::int32_t>::min();
  std::int32_t max_y = std::numeric_limits<std::int32_t>::min();

  void Extend(const ScreenVertex& vertex) {
    min_x = std::min(min_x, vertex.x);
    min_y = std::min(min_y, vertex.y);
    max_x = std::max(max_x, vertex.x);
    max_y = std::max(max_y, vertex.y);
  }
  // The pixel centres inside, as TrianglePixelBox computes them.
  PixelWindow Pixels() const {
    if (min_x > max_x) return PixelWindow{};
    const ScreenVertex low{min_x, min_y, 0.0f, 0};
    const ScreenVertex high{max_x, max_y, 0.0f, 0};
    const PixelWindow unbounded{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(),
                                std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
    return TrianglePixelBox(low, high, high, unbounded);
  }
};

// Adds the near-plane cuts of triangles crossing the near plane to `bounds`.
void AddNearPlaneCuts(const RenderMesh& mesh, const ScreenProjection& projection,
                      const ViewVertices& vertices, FixedBounds& bounds) {
  for (const auto& triangle : mesh.triangles) {
    std::uint32_t all = ~0u;
    std::uint32_t any = 0;
    for (const std::uint32_t index : triangle) {
      all &= vertices.screen[index].outcode;
      any |= vertices.screen[index].outcode;
    }
    if ((any & kBehindNear) == 0 || (all & kBehindNear) != 0 || (any & kInvalid) != 0) continue;
    const ClipPolygon polygon =
        ClipTriangle(vertices.in_cam[triangle[0]], vertices.in_cam[triangle[1]],
                     vertices.in_cam[triangle[2]], kBehindNear, projection);
    // Project clamps cuts beyond the guard band to its edge, which is outside the image.
    for (int i = 0; i < polygon.size; ++i) bounds.Extend(projection.Project(polygon.vertices[i]));
  }
}

// The z-buffered target of the visibility pass: nearest 1/z and triangle id per window pixel.
class DepthIdTarget {
 public:
  explicit DepthIdTarget(VisibilityBuffer& buffer)
      : depth_(buffer.inv_z.data()),
        ids_(buffer.triangle.data()),
        x0_(buffer.window.x0),
        y0_(buffer.window.y0),
        stride_(buffer.window.width()) {}

  float DepthAt(int x, int y) const { return depth_[Index(x, y)]; }
  // The farthest surface (smallest 1/z; 0 where none) in `box`.
  float FarthestIn(const PixelWindow& box) const {
    float farthest = std::numeric_limits<float>::infinity();
    for (int y = box.y0; y <= box.y1; ++y) {
      const float* row = depth_ + Index(box.x0, y);
      for (int i = 0; i < box.width(); ++i) farthest = std::min(farthest, row[i]);
    }
    return farthest;
  }
  // Keeps the fragment when it is inside and strictly nearer: on equal depth the triangle drawn
  // first stays. Blends with a bit mask rather than branching (see RasterizeTriangleInBox);
  // compilers turn a plain conditional here into a often-mispredicted branch.
  void Write(int x, int y, float inv_z, bool inside, std::int32_t id) const {
    const std::size_t pixel = Index(x, y);
    const bool nearer = inside & (inv_z > depth_[pixel]);
    const std::uint32_t keep_new = 0u - static_cast<std::uint32_t>(nearer);
    const auto new_depth = std::bit_cast<std::uint32_t>(inv_z);
    const auto old_depth = std::bit_cast<std::uint32_t>(depth_[pixel]);
    depth_[pixel] = std::bit_cast<float>((new_depth & keep_new) | (old_depth & ~keep_new));
    const auto new_id = static_cast<std::uint32_t>(id);
    const auto old_id = static_cast<std::uint32_t>(ids_[pixel]);
    ids_[pixel] = static_cast<std::int32_t>((new_id & keep_new) | (old_id & ~keep_new));
  }

 private:
  std::size_t Index(int x, int y) const {
    return static_cast<std::size_t>(y - y0_) * static_cast<std::size_t>(stride_) +
           static_cast<std::size_t>(x - x0_);
  }

  float* depth_;
  std::int32_t* ids_;
  int x0_;
  int y0_;
  int stride_;
};

// Triangles covering several pixels, and clipped ones, are rare in a dense mesh: kept out of line
// so the main loop stays small.
// The target is taken by value: a copy the compiler knows no pixel store can alias keeps its
// fields in registers.
[[gnu::noinline]] void DrawBox(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                               const PixelWindow& box, DepthIdTarget target, std::int32_t id) {
  RasterizeTriangleInBox(a, b, c, box, [&](int x, int y, float inv_z, bool inside) {
    target.Write(x, y, inv_z, inside, id);
  });
}

// Rasterizes the part of a triangle inside the clip planes as a fan of sub-triangles, all
// recorded under the original triangle's index.
[[gnu::noinline]] void DrawClipped(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                                   const Eigen::Vector3f& c, const ScreenProjection& projection,
                                   const PixelWindow& window, const DepthIdTarget& target,
                                   std::int32_t id) {
  // Every plane, not just those named by the outcodes: vertices behind the near plane carry
  // no side bits, yet their near-plane cuts may fall outside the guard band.
  const ClipPolygon polygon = ClipTriangle(a, b, c, kAllClipPlanes, projection);
  std::array<ScreenVertex, ClipPolygon::kMaxVertices> screen;
  for (int i = 0; i < polygon.size; ++i) screen[i] = projection.Project(polygon.vertices[i]);
  for (int i = 1; i + 1 < polygon.size; ++i) {
    const PixelWindow box = TrianglePixelBox(screen[0], screen[i], screen[i + 1], window);
    if (!box.empty()) DrawBox(screen[0], screen[i], screen[i + 1], box, target, id);
  }
}

// Draws a triangle whose corners are all in front and inside the guard band, given its
// non-empty pixel box.
inline void DrawTriangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                         const PixelWindow& box, DepthIdTarget target, std::int32_t id) {
  if (box.x0 != box.x1 || box.y0 != box.y1) {
    DrawBox(a, b, c, box, target, id);
    return;
  }
  // A single candidate pixel, the commonest case: skip even the edge set-up when the pixel
  // already shows something nearer than the triangle's nearest corner.
  if (std::max({a.inv_z, b.inv_z, c.inv_z}) <= target.DepthAt(box.x0, box.y0)) return;
  RasterizeTriangleAtPixel(a, b, c, box.x0, box.y0, [&](int x, int y, float inv_z, bool inside) {
    target.Write(x, y, inv_z, inside, id);
  });
}

}  // namespace

ViewVertices TransformVertices(const RenderMesh& mesh, const Pose& cam_from_model,
                               const ScreenProjection& projection) {
  const Eigen::Matrix3f rotation = cam_from_model.R.cast<float>();
  const Eigen::Vector3f translation = cam_from_model.t.cast<float>();
  const std::size_t count = mesh.positions.size();
  ViewVertices vertices;
  vertices.in_cam.resize(count);
  vertices.screen.resize(count);
  // Integer bounds, accumulated with selects so the loop has no branches.
  // A vertex in front but beyond the guard band is clamped to its edge, outside the image, which
  // is all the window needs to know.
  constexpr std::int32_t kMaxInt = std::numeric_limits<std::int32_t>::max();
  constexpr std::int32_t kMinInt = std::numeric_limits<std::int32_t>::min();
  std::int32_t min_x = kMaxInt, min_y = kMaxInt, max_x = kMinInt, max_y = kMinInt;
  std::uint32_t all_outcodes = 0;
  const Eigen::Vector3f* const positions = mesh.positions.data();
  Eigen::Vector3f* const in_cam = vertices.in_cam.data();
  ScreenVertex* const screen = vertices.screen.data();
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3f point = rotation * positions[i] + translation;
    in_cam[i] = point;
    projection.ProjectVertex(point, screen[i]);
    const std::uint32_t outcode = screen[i].outcode;
    all_outcodes |= outcode;
    const bool in_front = (outcode & kNotInFront) == 0;
    min_x = std::min(min_x, in_front ? screen[i].x : kMaxInt);
    min_y = std::min(min_y, in_front ? screen[i].y : kMaxInt);
    max_x = std::max(max_x, in_front ? screen[i].x : kMinInt);
    max_y = std::max(max_y, in_front ? screen[i].y : kMinInt);
  }
  FixedBounds bounds{min_x, min_y, max_x, max_y};
  vertices.any_behind_near = (all_outcodes & kBehindNear) != 0;
  if (vertices.any_behind_near) AddNearPlaneCuts(mesh, projection, vertices, bounds);
  vertices.covered_box = bounds.Pixels();
  return vertices;
}

VisibilityBuffer RasterizeVisibility(const RenderMesh& mesh, const ViewVertices& vertices,
                                     const ScreenProjection& projection,
                                     const PixelWindow& window) {
  VisibilityBuffer buffer;
  buffer.window = window;
  const std::size_t pixels = static_cast<std::size_t>(window.width()) * window.height();
  buffer.inv_z.assign(pixels, 0.0f);
  buffer.triangle.assign(pixels, -1);
  const DepthIdTarget target(buffer);
  const ScreenVertex* const screen = vertices.screen.data();
  const std::size_t triangle_count = mesh.triangles.size();
  // Triangles facing away (clockwise on screen) are drawn after the others: in a closed mesh with
  // the usual winding they are all hidden, and the early depth test then rejects them before
  // any edge set-up. For other meshes this costs only the sorting. The image is the same in any
  // order, except which of two surfaces at exactly the same depth wins: the first drawn, so the
  // result is still a function of the input alone.
  // The sort is branch-free (a branch on the orientation would be mispredicted half the time):
  // each id is written to both ends of `order`, and only the matching end advances.
  ScratchVector<std::int32_t> order(triangle_count);
  std::size_t facing_count = 0;
  std::size_t away_count = 0;
  for (std::size_t t = 0; t < triangle_count; ++t) {
    const auto& triangle = mesh.triangles[t];
    const ScreenVertex& a = screen[triangle[0]];
    const ScreenVertex& b = screen[triangle[1]];
    const ScreenVertex& c = screen[triangle[2]];
    // Clipped triangles stay in the first group: their screen coordinates are not exact.
    const bool away = ((a.outcode | b.outcode | c.outcode) == 0) & (SignedArea(a, b, c) > 0);
    order[facing_count] = static_cast<std::int32_t>(t);
    order[triangle_count - 1 - away_count] = static_cast<std::int32_t>(t);
    facing_count += away ? 0 : 1;
    away_count += away ? 1 : 0;
  }
  for (std::size_t i = 0; i < facing_count; ++i) {
    const std::int32_t id = order[i];
    const auto& triangle = mesh.triangles[static_cast<std::size_t>(id)];
    const ScreenVertex& a = screen[triangle[0]];
    const ScreenVertex& b = screen[triangle[1]];
    const ScreenVertex& c = screen[triangle[2]];
    const std::uint32_t any = a.outcode | b.outcode | c.outcode;
    if (any != 0) {
      if ((a.outcode & b.outcode & c.outcode) == 0 && (any & kInvalid) == 0) {
        DrawClipped(vertices.in_cam[triangle[0]], vertices.in_cam[triangle[1]],
                    vertices.in_cam[triangle[2]], projection, window, target, id);
      }
      continue;
    }
    const PixelWindow box = TrianglePixelBox(a, b, c, window);
    if (!box.empty()) DrawTriangle(a, b, c, box, target, id);
  }
  constexpr int kEarlyTestMaxPixels = 64;         // beyond this the test rarely pays
  for (std::size_t i = 0; i < away_count; ++i) {  // in mesh order, as stored from the end
    const std::int32_t id = order[triangle_count - 1 - i];
    const auto& triangle = mesh.triangles[static_cast<std::size_t>(id)];
    const ScreenVertex& a = screen[triangle[0]];
    const ScreenVertex& b = screen[triangle[1]];
    const ScreenVertex& c = screen[triangle[2]];
    const PixelWindow box = TrianglePixelBox(a, b, c, window);
    if (box.empty()) continue;
    // Single pixels get the same test inside DrawTriangle.
    const int box_pixels = box.width() * box.height();
    if (box_pixels > 1 && box_pixels <= kEarlyTestMaxPixels &&
        std::max({a.inv_z, b.inv_z, c.inv_z}) <= target.FarthestIn(box)) {
      continue;
    }
    DrawTriangle(a, b, c, box, target, id);
  }
  return buffer;
}

}  // namespace layermod::render_internal
