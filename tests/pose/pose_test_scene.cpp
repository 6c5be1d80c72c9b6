// SPDX-License-Identifier: MIT
#include "pose/pose_test_scene.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "geometry/views.h"
#include "render/rasterizer.h"
#include "support/test_paths.h"

namespace layermod::test {

const Model& SampleModel() {
  static const Model model = LoadModel(SourceDir() / "resources/sample/bracket.ply");
  return model;
}

const RenderMesh& SampleRenderMesh() {
  static const RenderMesh mesh = ToRenderMesh(SampleModel());
  return mesh;
}

Pose SamplePose(double distance_mm) {
  Pose pose = CamFromModelForView({40.0, 35.0, 10.0}, SampleModel().sphere.centre, distance_mm);
  pose.t += Eigen::Vector3d(60.0, -30.0, 0.0);  // off the optical axis
  return pose;
}

TestScene RenderTestScene(const Pose& pose, double wall_mm) {
  RenderOptions options;
  options.window = RenderWindow::kFullImage;
  const RenderedView view = RenderView(SampleRenderMesh(), VgaCamera(), pose, options);
  TestScene scene;
  scene.depth_mm = view.depth_mm.clone();
  scene.depth_mm.setTo(static_cast<float>(wall_mm), view.mask == 0);
  scene.color = view.color.clone();
  scene.color.setTo(cv::Scalar(90, 60, 40), view.mask == 0);
  return scene;
}

Pose Perturb(const Pose& pose, double angle_deg, const Eigen::Vector3d& axis,
             const Eigen::Vector3d& shift_mm) {
  const Eigen::Vector3d centre = pose * SampleModel().sphere.centre;
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(DegToRad(angle_deg), axis.normalized()).toRotationMatrix();
  Pose moved;
  moved.R = rotation * pose.R;
  moved.t = rotation * (pose.t - centre) + centre + shift_mm;
  return moved;
}

double RotationErrorDeg(const Pose& a, const Pose& b) {
  const double cosine = std::clamp(((a.R.transpose() * b.R).trace() - 1.0) / 2.0, -1.0, 1.0);
  return RadToDeg(std::acos(cosine));
}

}  // namespace layermod::test
