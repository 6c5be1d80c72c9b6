// SPDX-License-Identifier: MIT
// Depth-edge counts of templates, which coarse positioning compares with scene patches
// (paper §3.3: N_max and N_min of Table 2 and Eq. 5).
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "render/rasterizer.h"

namespace layermod {

// The plane a part stands on: z = z_mm in model coordinates (+Z up), seen from the template's
// pose. Parts in a scene rest on a table or in a bin, so along much of their silhouette the
// depth step is small; counting template edges against this plane (not against infinity)
// makes template and scene counts comparable.
struct SupportPlane {
  Pose cam_from_model;
  double z_mm = 0.0;
};

// Depth (z, mm) of the support plane through each pixel of `window` (camera pixels), `far_mm`
// where a ray misses the plane or meets it beyond `far_mm`. CV_32F of the window's size.
cv::Mat SupportPlaneDepth(const PinholeCamera& camera, const SupportPlane& plane,
                          const cv::Rect& window, float far_mm);

// Number of depth-edge pixels in the L x L window (L = f * diameter / layer depth) centred on
// `centre_px` (camera pixels) of a rendered view. Behind the object lies `support` when given,
// else a background 2 diameters behind the layer.
int TemplateDepthEdgeCount(const RenderedView& view, const PinholeCamera& camera,
                           const cv::Point2d& centre_px, double diameter_mm, double layer_depth_mm,
                           float edge_threshold_mm, const SupportPlane* support = nullptr);

}  // namespace layermod
