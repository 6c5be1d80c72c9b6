// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "mesh/render_mesh.h"
#include "templates/template_record.h"

namespace layermod {

// The template's view rendered at its pose with its level-0 features drawn on it (colour
// gradients green, normals red/blue, as the paper's Fig. 4). Without a mesh, or when the mesh
// renders nothing at that pose, the features alone on black around their bounding box. BGR
// CV_8UC3; empty when there is nothing to draw. Shared by `layermod render` and the studio's
// template browser.
cv::Mat RenderTemplatePicture(const TemplateRecord& record, const PinholeCamera& camera,
                              const RenderMesh* mesh);

// `image` scaled to fit a `size_px` square, centred on black (a template thumbnail). Enlargements
// keep hard pixels so single features stay readable; reductions average.
cv::Mat FitInSquare(const cv::Mat& image, int size_px);

}  // namespace layermod
