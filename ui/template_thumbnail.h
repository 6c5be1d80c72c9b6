// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "mesh/render_mesh.h"
#include "templates/template_record.h"

namespace layermod::ui {

// The template's view rendered at its pose with its level-0 features drawn on it (colour
// gradients green, normals red/blue, as the paper's Fig. 4). Without a mesh: the features alone
// on black. BGR CV_8UC3; empty when there is nothing to draw.
cv::Mat RenderTemplateImage(const TemplateRecord& record, const PinholeCamera& camera,
                            const RenderMesh* mesh);

// `image` scaled to fit a `size_px` square, centred on black. Enlargements keep hard pixels so
// single features stay readable; reductions average.
cv::Mat FitInSquare(const cv::Mat& image, int size_px);

}  // namespace layermod::ui
