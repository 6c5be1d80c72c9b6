// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "mesh/render_mesh.h"

namespace layermod {

// Rejects false positives by comparing the model rendered at the pose with the scene.
struct VerificationOptions {
  double depth_tolerance_mm = 15.0;  // |scene - model| within this: consistent
  double min_depth_inlier_ratio = 0.6;
  double min_visible_ratio = 0.3;  // consistent + occluded pixels over the silhouette
  double hue_tolerance_deg = 30.0;
  double min_color_agreement = 0.5;  // only judged when the model has saturated colours

  void Validate() const;  // throws Error
};

struct Verification {
  double depth_inlier_ratio = 0.0;  // consistent / (consistent + surface missing or behind)
  double visible_ratio = 0.0;       // silhouette pixels not contradicted by the scene
  double color_agreement = 1.0;     // saturated pixels whose hue matches (1 when not judged)
  // How closely the depth agrees, on the pixels the inlier ratio judges: the mean of
  // max(0, 1 - |scene - model| / tolerance), 1 for an exact fit. Unlike the inlier ratio it
  // tells a pose a few millimetres off (a neighbouring rotation after ICP) from the true one.
  double depth_fit = 0.0;
  // Over the silhouette pixels the scene measures: a nearer scene (an occluder in front) and a
  // farther one (the model's surface is not there).
  double occluded_ratio = 0.0;
  double contradicted_ratio = 0.0;
  // In a thin ring just outside the silhouette: the share of measured pixels whose depth
  // continues the model's nearby surface. A model laid over part of a larger surface (a wrong
  // template on a box, a wall, the table) has its outline where the scene has none.
  double surface_continuation = 0.0;
  // Along the silhouette's outline, where the scene does not hide it: the share of outline
  // pixels with a scene colour gradient of the outline's orientation (one 22.5 deg bin either
  // way) within kOutlineReachPx. A part's outline is where texture-less parts show their edges
  // (LINE-2D); a pose turned or shifted from the true one puts its outline beside them.
  // 0 when no gradient labels were given.
  double outline_agreement = 0.0;
  int silhouette_px = 0;  // about: counted on every second pixel of every second row
  bool accepted = false;
};

// The scene's colour-gradient labels at level 0 (QuantizeColorGradients) over part of the
// capture: labels.at(y, x) is capture pixel (x + offset.x, y + offset.y).
struct GradientLabels {
  cv::Mat labels;
  cv::Point offset;
};

// Depth consistency: on the model's silhouette, scene depth within tolerance is consistent, a
// scene nearer than the model is an occluder (neither for nor against), a scene farther means the
// object is not there. Colour check (Hinterstoisser ACCV 2012): hue agreement on pixels where
// the model's colour is saturated. Without depth (empty `depth_mm`) only colour is judged.
// Every second pixel of every second row is rendered and judged.
Verification VerifyPose(const RenderMesh& mesh, const PinholeCamera& camera, const Pose& pose,
                        const cv::Mat& depth_mm, const cv::Mat& color_bgr,
                        const VerificationOptions& options = {},
                        const GradientLabels& gradients = {});

}  // namespace layermod
