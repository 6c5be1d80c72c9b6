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

  void Validate() const;
};

// A rendered view. All images cover `roi` (a window of the camera image, in camera pixels);
// pixel (0,0) of each image is pixel roi.tl() of the camera image.
struct RenderedView {
  cv::Rect roi;
  cv::Mat depth_mm;    // CV_32F, z in camera frame (mm); 0 where no surface
  cv::Mat mask;        // CV_8U, 255 on the object, 0 elsewhere
  cv::Mat normals;     // CV_32FC3, unit surface normal in camera frame (towards camera); 0 outside
  cv::Mat color;       // CV_8UC3 BGR, vertex colour x Lambert; black outside

  bool empty() const { return roi.area() == 0 || cv::countNonZero(mask) == 0; }
};

// Renders `mesh` seen by `camera` at `cam_from_model`. Pixel-centre sampling, z-buffer, exact
// pinhole projection, triangles clipped at the near plane. Deterministic. Thread-safe (no shared
// state), so callers render views in parallel. A mesh entirely outside the image gives an empty view.
RenderedView RenderView(const RenderMesh& mesh, const PinholeCamera& camera,
                        const Pose& cam_from_model, const RenderOptions& options = {});

}  // namespace layermod
