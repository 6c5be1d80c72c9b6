// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "mesh/render_mesh.h"

namespace layermod {

enum class RenderWindow {
  kObjectOnly,  // only the object's projected bounding box (plus padding): fast, for training
  kFullImage,   // the whole camera image: for synthetic scenes
};

struct RenderOptions {
  RenderWindow window = RenderWindow::kObjectOnly;
  int padding_px = 8;  // border around the object's window, clipped to the image
  // Light direction in camera coordinates (towards the light) for Lambert shading of colours.
  Eigen::Vector3f light_dir_in_cam{0.0f, 0.0f, -1.0f};
  float ambient = 0.35f;  // ambient term; diffuse term is (1 - ambient)
  // Surfaces at z <= near_mm are clipped away (triangles crossing it are cut, not dropped).
  float near_mm = 1.0f;

  // Throws Error for negative padding, ambient outside [0, 1], a zero or non-finite light
  // direction, or a near plane that is not a positive finite distance.
  void Validate() const;
};

// A rendered view. All images cover `roi` (a window of the camera image, in camera pixels);
// pixel (0,0) of each image is pixel roi.tl() of the camera image.
struct RenderedView {
  cv::Rect roi;
  cv::Mat depth_mm;  // CV_32F, z in camera frame (mm); 0 where no surface
  cv::Mat mask;      // CV_8U, 255 on the object, 0 elsewhere
  // CV_32FC3, unit surface normal in camera frame (towards camera); 0 outside. These are face
  // normals (flat per triangle): exact for planar parts, deterministic, and independent of how
  // the mesh's vertices are shared.
  cv::Mat normals;
  // CV_8UC3 BGR, vertex colour (perspective-correct; light grey when the mesh has no colours) x
  // (ambient + (1 - ambient) * max(0, normal . light)); black outside.
  cv::Mat color;

  bool empty() const { return roi.area() == 0 || cv::countNonZero(mask) == 0; }
};

// Renders `mesh` seen by `camera` at `cam_from_model`. Pixel-centre sampling (a pixel is covered
// when its centre is inside the projected triangle; shared edges follow the top-left rule, so
// they are drawn once, without gaps), z-buffer, exact pinhole projection, depth = exact z of the
// surface point seen through the pixel centre, triangles clipped at the near plane. No culling:
// meshes need not be closed. Deterministic. Thread-safe (no shared state), so callers render views
// in parallel.
// kObjectOnly: roi = the projected bounding box of the surface in front of the near plane, padded
// by padding_px and clipped to the image; a mesh entirely outside the image or behind the camera
// gives a default RenderedView (zero-area roi, empty mats). kFullImage: roi = the whole image,
// always (black and empty() when nothing is visible).
// Throws Error for invalid options, camera, or mesh (colour count, out-of-range index).
RenderedView RenderView(const RenderMesh& mesh, const PinholeCamera& camera,
                        const Pose& cam_from_model, const RenderOptions& options = {});

}  // namespace layermod
