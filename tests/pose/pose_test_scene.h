// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "mesh/model.h"
#include "support/test_cameras.h"

namespace layermod::test {

// The bundled sample part, its render mesh and a VGA camera.
const Model& SampleModel();
const RenderMesh& SampleRenderMesh();

// A ground-truth pose of the sample at `distance_mm`, seen from above and off-centre.
Pose SamplePose(double distance_mm);

// Depth (CV_32F mm) of the sample at `pose` in front of a wall at `wall_mm`; colour render too.
struct TestScene {
  cv::Mat depth_mm;
  cv::Mat color;
};
TestScene RenderTestScene(const Pose& pose, double wall_mm = 1200.0);

// `pose` moved by a rotation of `angle_deg` about `axis` (through the sphere centre) and a shift.
Pose Perturb(const Pose& pose, double angle_deg, const Eigen::Vector3d& axis,
             const Eigen::Vector3d& shift_mm);

double RotationErrorDeg(const Pose& a, const Pose& b);

}  // namespace layermod::test
