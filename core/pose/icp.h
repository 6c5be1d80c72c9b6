// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "mesh/render_mesh.h"

namespace layermod {

struct IcpOptions {
  // 45: with accelerated steps (icp.cpp) the extra iterations finish turns in the plane of a
  // flat face; without them a longer ICP let wrong poses fit too (docs/NOTES.md).
  int max_iterations = 45;
  int renders = 3;                        // visible-surface re-samplings during refinement
  double initial_max_distance_mm = 40.0;  // correspondence gate, shrinking towards...
  double final_max_distance_mm = 8.0;     // ... this
  double huber_mm = 3.0;                  // robust loss scale
  int sample_step_px = 3;                 // visible-surface sampling step
  double convergence_mm = 0.05;           // stop when an update moves points less than this
  // A part lying flat on a table leaves point-to-plane ICP free to slide along the plane. Each
  // step is damped and clamped, and a refinement that wanders farther than this from its start
  // is abandoned (the initial pose is returned, not converged).
  double max_step_mm = 10.0;
  double max_step_deg = 5.0;
  double max_drift_mm = 60.0;
  double max_drift_deg = 30.0;

  void Validate() const;  // throws Error
};

struct IcpResult {
  Pose cam_from_model;
  double rmse_mm = 0.0;       // point-to-plane RMS over inliers at the end
  double inlier_ratio = 0.0;  // visible samples with a scene point within the final gate
  int iterations = 0;
  bool converged = false;
};

// Point-to-plane ICP of the model's visible surface against the scene depth (projective
// association, Huber weights). The visible surface is re-sampled from renders at the current pose,
// so self-occluded parts never pull the pose. The scene depth is CV_32F mm, 0 = invalid.
IcpResult RefinePoseIcp(const RenderMesh& mesh, const PinholeCamera& camera,
                        const cv::Mat& depth_mm, const Pose& initial,
                        const IcpOptions& options = {});

}  // namespace layermod
