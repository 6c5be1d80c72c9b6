// SPDX-License-Identifier: MIT
#include "ui/scene3d/scene_view.h"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkMapper.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include <cmath>

#include "ui/scene3d/detection_actors.h"
#include "ui/scene3d/scene_actors.h"

namespace layermod::ui {
namespace {

// Direction the default view looks from (object +Z up), as a CAD viewer's isometric view.
constexpr ViewAngles kHomeView{-60.0, 25.0, 0.0};
constexpr double kHomeViewAngleDeg = 30.0;
// The capture's points shown around a detection: within this many sphere radii of its centre.
constexpr double kDetectionCloudRadii = 2.5;

}  // namespace

SceneView::SceneView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  setRenderWindow(window);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->SetBackground(0.13, 0.14, 0.17);
  renderer_->SetBackground2(0.32, 0.34, 0.40);
  renderer_->GradientBackgroundOn();
  window->AddRenderer(renderer_);
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor()->SetInteractorStyle(style);

  auto marker_axes = vtkSmartPointer<vtkAxesActor>::New();
  orientation_ = vtkSmartPointer<vtkOrientationMarkerWidget>::New();
  orientation_->SetOrientationMarker(marker_axes);
  orientation_->SetInteractor(interactor());
  orientation_->SetViewport(0.0, 0.0, 0.16, 0.22);
  orientation_->SetEnabled(1);
  orientation_->InteractiveOff();
  setMinimumSize(320, 240);
}

SceneView::~SceneView() = default;

void SceneView::RemoveModelActors() {
  for (const auto& prop : model_props_) renderer_->RemoveViewProp(prop);
  model_props_.clear();
  sphere_ = nullptr;
}

void SceneView::SetModel(std::shared_ptr<const Model> model) {
  RemoveModelActors();
  ClearHighlight();
  ClearDetection();
  SetGroundTruthViews({});
  model_ = std::move(model);
  if (model_ != nullptr) {
    sphere_ = MakeSphereActor(model_->sphere);
    sphere_->SetVisibility(sphere_visible_);
    model_props_ = {MakeMeshActor(*model_), sphere_, MakeCentreMarker(model_->sphere),
                    MakeAxesActor(model_->sphere.radius_mm * 0.8)};
    for (const auto& prop : model_props_) renderer_->AddViewProp(prop);
  }
  ResetCamera();
}

void SceneView::SetCoverage(const std::vector<double>& layer_depths_mm,
                            const std::vector<ViewAngles>& views,
                            const Eigen::Matrix3d& upright_from_model) {
  for (const auto& prop : {coverage_, up_arrow_}) {
    if (prop != nullptr) renderer_->RemoveViewProp(prop);
  }
  if (scalar_bar_ != nullptr) renderer_->RemoveViewProp(scalar_bar_);
  coverage_ = nullptr;
  up_arrow_ = nullptr;
  scalar_bar_ = nullptr;
  coverage_glyphs_ = 0;
  coverage_radius_mm_ = 0.0;
  upright_from_model_ = upright_from_model;
  nearest_layer_mm_ = layer_depths_mm.empty() ? 0.0 : layer_depths_mm.front();
  if (model_ != nullptr) {
    coverage_ = MakeCoverageActor(model_->sphere, upright_from_model, layer_depths_mm, views,
                                  &coverage_glyphs_);
    up_arrow_ = MakeUpArrowActor(model_->sphere, upright_from_model);
    renderer_->AddViewProp(up_arrow_);
  }
  if (coverage_ != nullptr) {
    coverage_radius_mm_ =
        ShellRadiusMm(model_->sphere, layer_depths_mm.back(), layer_depths_mm.front());
  }
  if (coverage_ != nullptr) {
    scalar_bar_ = MakeDepthScalarBar(coverage_);
    ShowCoverageActors(coverage_visible_ && !has_detection());
    renderer_->AddViewProp(coverage_);
    renderer_->AddViewProp(scalar_bar_);
  }
  Render();
}

void SceneView::ShowTemplateCamera(const TemplateRecord& record, const PinholeCamera& camera,
                                   const std::vector<double>& layer_depths_mm) {
  if (model_ == nullptr || layer_depths_mm.empty()) return;
  ClearHighlight();
  const Sphere& sphere = model_->sphere;
  highlight_ =
      MakeHighlightActor(sphere, GlyphPosition(sphere, upright_from_model_, record.view,
                                               record.layer_depth_mm, layer_depths_mm.front()));
  renderer_->AddViewProp(highlight_);

  // The template's pose and field of view show the model as in the template's render. Only the
  // model's depth is kept, which hides the glyphs between that camera and the model until the
  // user moves the view.
  LookThrough(record.cam_from_model, camera, sphere, 1.5 * sphere.radius_mm);
  Render();
}

void SceneView::SetGroundTruthViews(const std::vector<GroundTruthCoverage>& coverage) {
  for (const auto& prop : ground_truth_props_) renderer_->RemoveViewProp(prop);
  ground_truth_props_.clear();
  if (model_ != nullptr) {
    for (const GroundTruthCoverage& instance : coverage) {
      if (!instance.check.has_value()) continue;
      const EnvelopeCheck& check = *instance.check;
      const double nearest_mm = nearest_layer_mm_ > 0.0 ? nearest_layer_mm_ : check.depth_mm;
      const Eigen::Vector3d at =
          GlyphPosition(model_->sphere, upright_from_model_,
                        {check.azimuth_deg, check.elevation_deg, 0.0}, check.depth_mm, nearest_mm);
      const Eigen::Vector3d rgb =
          check.inside ? Eigen::Vector3d(1.0, 1.0, 1.0) : Eigen::Vector3d(1.0, 0.25, 0.25);
      ground_truth_props_.push_back(MakeHighlightActor(model_->sphere, at, rgb));
      renderer_->AddViewProp(ground_truth_props_.back());
    }
  }
  Render();
}

void SceneView::LookThrough(const Pose& pose, const PinholeCamera& camera, const Sphere& sphere,
                            double depth_margin_mm) {
  const Eigen::Vector3d position = -(pose.R.transpose() * pose.t);
  const Eigen::Vector3d forward = pose.R.transpose() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d up = -(pose.R.transpose() * Eigen::Vector3d::UnitY());
  const double distance_mm = (sphere.centre - position).dot(forward);
  const Eigen::Vector3d focal = position + forward * distance_mm;
  vtkCamera* vtk_camera = renderer_->GetActiveCamera();
  vtk_camera->SetPosition(position.data());
  vtk_camera->SetFocalPoint(focal.data());
  vtk_camera->SetViewUp(up.data());
  if (camera.fy > 0.0 && camera.height > 0) {
    vtk_camera->SetViewAngle(RadToDeg(2.0 * std::atan(0.5 * camera.height / camera.fy)));
  }
  vtk_camera->SetClippingRange(std::max(distance_mm - depth_margin_mm, 1.0),
                               distance_mm + depth_margin_mm);
}

void SceneView::ShowDetection(const Capture& capture, const ArchiveObject& object,
                              const Detection& detection) {
  ClearDetection();
  const double keep_radius_mm = kDetectionCloudRadii * object.sphere.radius_mm;
  auto cloud = MakeCaptureCloudActor(capture, detection.cam_from_model, object.sphere,
                                     keep_radius_mm, &detection_cloud_points_);
  if (cloud != nullptr) detection_props_.push_back(cloud);
  detection_props_.push_back(MakeDetectedModelActor(object.mesh));
  for (const auto& prop : detection_props_) renderer_->AddViewProp(prop);
  // The glyphs would hide the points; the View menu can bring them back.
  ShowCoverageActors(false);
  LookAtFrom(detection.cam_from_model, object.sphere, keep_radius_mm);
  Render();
}

void SceneView::LookAtFrom(const Pose& cam_from_model, const Sphere& sphere, double fit_radius_mm) {
  const Eigen::Vector3d position = -(cam_from_model.R.transpose() * cam_from_model.t);
  const Eigen::Vector3d up = -(cam_from_model.R.transpose() * Eigen::Vector3d::UnitY());
  const double distance_mm = (sphere.centre - position).norm();
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetPosition(position.data());
  camera->SetFocalPoint(sphere.centre.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(RadToDeg(2.0 * std::atan(fit_radius_mm / std::max(distance_mm, 1.0))));
  renderer_->ResetCameraClippingRange();
}

void SceneView::ShowCoverageActors(bool visible) {
  if (coverage_ != nullptr) coverage_->SetVisibility(visible);
  if (scalar_bar_ != nullptr) scalar_bar_->SetVisibility(visible);
}

void SceneView::ClearDetection() {
  for (const auto& prop : detection_props_) renderer_->RemoveViewProp(prop);
  detection_props_.clear();
  detection_cloud_points_ = 0;
  ShowCoverageActors(coverage_visible_);
}

void SceneView::ClearHighlight() {
  if (highlight_ != nullptr) renderer_->RemoveViewProp(highlight_);
  highlight_ = nullptr;
}

void SceneView::ResetCamera() {
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetViewAngle(kHomeViewAngleDeg);
  camera->SetViewUp(0.0, 0.0, 1.0);
  const Eigen::Vector3d direction(
      std::cos(DegToRad(kHomeView.elevation_deg)) * std::cos(DegToRad(kHomeView.azimuth_deg)),
      std::cos(DegToRad(kHomeView.elevation_deg)) * std::sin(DegToRad(kHomeView.azimuth_deg)),
      std::sin(DegToRad(kHomeView.elevation_deg)));
  if (model_ == nullptr) {
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(direction.data());
    renderer_->ResetCamera();
  } else {
    // Centred on the sphere, framing the whole coverage (every glyph shell) or else the model.
    const Sphere& sphere = model_->sphere;
    const double fit_radius_mm =
        std::max(sphere.radius_mm * 1.3, coverage_ != nullptr ? coverage_radius_mm_ * 1.05 : 0.0);
    const double distance_mm = fit_radius_mm / std::sin(DegToRad(kHomeViewAngleDeg / 2.0));
    const Eigen::Vector3d position = sphere.centre + distance_mm * direction;
    camera->SetFocalPoint(sphere.centre.data());
    camera->SetPosition(position.data());
  }
  renderer_->ResetCameraClippingRange();
  Render();
}

void SceneView::SetCoverageVisible(bool visible) {
  coverage_visible_ = visible;
  ShowCoverageActors(visible);
  Render();
}

void SceneView::SetSphereVisible(bool visible) {
  sphere_visible_ = visible;
  if (sphere_ != nullptr) sphere_->SetVisibility(visible);
  Render();
}

void SceneView::Render() { renderWindow()->Render(); }

}  // namespace layermod::ui
