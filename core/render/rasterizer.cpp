// SPDX-License-Identifier: MIT
#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "render/screen_projection.h"
#include "render/shading.h"
#include "render/visibility.h"
#include "util/error.h"

namespace layermod {

void RenderOptions::Validate() const {
  if (padding_px < 0) throw Error("render options: padding_px must not be negative");
  if (!(ambient >= 0.0f && ambient <= 1.0f)) {
    throw Error("render options: ambient must be between 0 and 1");
  }
  if (!light_dir_in_cam.allFinite() || light_dir_in_cam.squaredNorm() <= 0.0f) {
    throw Error("render options: light_dir_in_cam must be a finite, non-zero direction");
  }
  if (!(std::isfinite(near_mm) && near_mm > 0.0f)) {
    throw Error("render options: near_mm must be a positive finite distance");
  }
}

namespace {

using render_internal::PixelWindow;

void ValidateMesh(const RenderMesh& mesh) {
  if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) {
    throw Error("render mesh: " + std::to_string(mesh.colors.size()) + " colours for " +
                std::to_string(mesh.positions.size()) + " vertices");
  }
  // Triangle ids are stored as int32 in the visibility buffer.
  if (mesh.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
    throw Error("render mesh: too many triangles");
  }
  std::uint32_t max_index = 0;
  for (const auto& triangle : mesh.triangles) {
    max_index = std::max({max_index, triangle[0], triangle[1], triangle[2]});
  }
  if (!mesh.triangles.empty() && max_index >= mesh.positions.size()) {
    throw Error("render mesh: triangle index " + std::to_string(max_index) + " out of range for " +
                std::to_string(mesh.positions.size()) + " vertices");
  }
}

// The object's window: the pixels it may cover, clipped to the image and padded. Empty when it
// covers no pixel centre of the image.
PixelWindow ObjectWindow(const PixelWindow& covered, const PinholeCamera& camera, int padding_px) {
  PixelWindow window{std::max(covered.x0, 0), std::max(covered.y0, 0),
                     std::min(covered.x1, camera.width - 1),
                     std::min(covered.y1, camera.height - 1)};
  if (window.empty()) return PixelWindow{};
  window.x0 = std::max(window.x0 - padding_px, 0);
  window.y0 = std::max(window.y0 - padding_px, 0);
  window.x1 = std::min(window.x1 + padding_px, camera.width - 1);
  window.y1 = std::min(window.y1 + padding_px, camera.height - 1);
  return window;
}

}  // namespace

RenderedView RenderView(const RenderMesh& mesh, const PinholeCamera& camera,
                        const Pose& cam_from_model, const RenderOptions& options) {
  options.Validate();
  camera.Validate();
  ValidateMesh(mesh);
  const render_internal::ScreenProjection projection(camera, options.near_mm);
  const render_internal::ViewVertices vertices =
      render_internal::TransformVertices(mesh, cam_from_model, projection);
  // The rasterizer only visits the object's pixels; kFullImage then pads with zeros, which gives
  // the same bits inside the object window as kObjectOnly.
  const bool full_image = options.window == RenderWindow::kFullImage;
  const PixelWindow window =
      ObjectWindow(vertices.covered_box, camera, full_image ? 0 : options.padding_px);
  const PixelWindow output =
      full_image ? PixelWindow{0, 0, camera.width - 1, camera.height - 1} : window;
  if (window.empty()) return full_image ? render_internal::BlankView(output) : RenderedView{};
  const render_internal::VisibilityBuffer buffer =
      render_internal::RasterizeVisibility(mesh, vertices, projection, window);
  return render_internal::ShadeVisibility(mesh, vertices.in_cam, buffer, camera, options, output);
}

}  // namespace layermod
