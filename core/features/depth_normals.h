// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "features/normal_frame.h"
#include "geometry/camera.h"

namespace layermod {

// Unit surface normals (CV_32FC3, in `frame`, facing the camera: n . ray < 0) from a CV_32F depth
// map in mm, 0 where no normal can be estimated. Pixel (u, v) of `depth_mm` is camera pixel
// (u + roi_offset.x, v + roi_offset.y). Each normal is a least-squares plane fit over the 5x5
// window: on a plane, inverse depth is exactly affine in the pixel coordinates, so the fit is exact
// for planes seen anywhere in the image with the real intrinsics. Neighbours with invalid depth
// (<= 0, NaN, inf) or whose depth differs from the centre's by more than `max_depth_step_mm` are
// ignored; fewer than 6 usable samples, or samples that do not span both image directions, give
// no normal. Works on any image size (template windows and whole scenes). `where` (optional,
// CV_8U of the same size) limits the work to its non-zero pixels; the others get 0.
cv::Mat ComputeDepthNormals(const cv::Mat& depth_mm, const PinholeCamera& camera,
                            cv::Point roi_offset, float max_depth_step_mm, NormalFrame frame,
                            const cv::Mat& where = cv::Mat());

// `normal` (camera frame) in the viewing-ray frame of the pixel whose normalized image
// coordinates are (xn, yn) = ((u - cx) / fx, (v - cy) / fy). Linear: 0 stays 0.
cv::Vec3f InViewingRayFrame(const cv::Vec3f& normal, float xn, float yn);

}  // namespace layermod
