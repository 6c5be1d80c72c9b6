// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "templates/template_record.h"

namespace layermod {

// Depth of the object's sphere centre for a template matched with its level-0 box top-left at
// `box_tl_px`: median scene depth under the template's depth-normal features (they lie on the
// object's surface) plus the template's centre-minus-surface offset. 0 when the scene has no
// valid depth there.
double EstimateCentreDepthMm(const TemplateRecord& tmpl, cv::Point box_tl_px,
                             const cv::Mat& depth_mm);

// Pose of a match: the template's rotation, corrected for the viewing ray through the matched
// sphere-centre pixel (a template is rendered on the optical axis; off-axis the same appearance
// means a rotation about the camera centre), and the centre placed at `centre_depth_mm` on that
// ray. `model_centre` is the sphere centre in model coordinates.
Pose PoseFromMatch(const TemplateRecord& tmpl, cv::Point box_tl_px, double centre_depth_mm,
                   const Eigen::Vector3d& model_centre, const PinholeCamera& camera);

}  // namespace layermod
