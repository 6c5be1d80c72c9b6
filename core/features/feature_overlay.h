// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "features/extraction.h"
#include "render/rasterizer.h"

namespace layermod {

// The view's colour image (grey shading of the mask when the colour is black) with the template's
// level-0 features drawn on it, as in the LineMOD paper's Fig. 4: a colour-gradient feature is a
// green pixel with a darker green tick along its gradient orientation, a normal feature a red pixel
// with a short blue tick towards its label's (nx, ny) direction. CV_8UC3 of the roi size.
cv::Mat RenderFeatureOverlay(const RenderedView& view, const ExtractedTemplate& tmpl);

}  // namespace layermod
