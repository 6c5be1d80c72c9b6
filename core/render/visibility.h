// SPDX-License-Identifier: MIT
// Internal to the rasterizer: the per-view vertex pass and the visibility buffer (nearest
// triangle per pixel), which is shaded afterwards, once per covered pixel.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

#include "geometry/pose.h"
#include "mesh/render_mesh.h"
#include "render/screen_projection.h"
#include "render/triangle_raster.h"

namespace layermod::render_internal {

// Allocates without value-initialising, for per-view arrays that are overwritten at once: zeroing
// them first was a measurable share of the vertex pass.
template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  template <typename U>
  void construct(U* pointer) noexcept {
    ::new (static_cast<void*>(pointer)) U;
  }
  template <typename U, typename... Args>
  void construct(U* pointer, Args&&... args) {
    ::new (static_cast<void*>(pointer)) U(std::forward<Args>(args)...);
  }
};
template <typename T>
using ScratchVector = std::vector<T, UninitializedAllocator<T>>;

// Every mesh vertex transformed for one view.
struct ViewVertices {
  ScratchVector<Eigen::Vector3f> in_cam;  // camera frame, mm
  ScratchVector<ScreenVertex> screen;
  // Pixels whose centres lie in the bounding box of everything in front of the near plane
  // (vertices, and the near-plane cuts of triangles crossing it), in the same snapped
  // coordinates as the rasterizer, so every pixel it may cover is inside. Not clipped to the
  // image: it may reach into the guard band; empty when nothing is in front.
  PixelWindow covered_box;
  bool any_behind_near = false;
};

// Transforms and projects the vertices; `mesh` must have valid triangle indices.
ViewVertices TransformVertices(const RenderMesh& mesh, const Pose& cam_from_model,
                               const ScreenProjection& projection);

struct VisibilityBuffer {
  PixelWindow window;
  std::vector<float> inv_z;            // 1/z of the nearest surface; 0 where none
  std::vector<std::int32_t> triangle;  // its triangle index; -1 where none
};

// Z-buffered scan conversion of every triangle into `window`. Triangles facing the camera (by the
// usual counter-clockwise winding) are drawn first, then those facing away, each group in mesh
// order; equal depths keep the triangle drawn first, so the result depends only on the input.
VisibilityBuffer RasterizeVisibility(const RenderMesh& mesh, const ViewVertices& vertices,
                                     const ScreenProjection& projection, const PixelWindow& window);

}  // namespace layermod::render_internal
