// SPDX-License-Identifier: MIT
#pragma once

#include <QVTKOpenGLNativeWidget.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

#include "eval/envelope_coverage.h"
#include "geometry/camera.h"
#include "geometry/views.h"
#include "mesh/model.h"
#include "pipeline/detector.h"
#include "templates/template_record.h"

class vtkActor;
class vtkAxesActor;
class vtkOrientationMarkerWidget;
class vtkProp;
class vtkRenderer;
class vtkScalarBarActor;

namespace layermod::ui {

// The central 3D view: the model, its circumscribing sphere, centre and axes, the training
// coverage (camera glyphs per depth layer) and one highlighted template camera.
class SceneView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit SceneView(QWidget* parent = nullptr);
  ~SceneView() override;

  void SetModel(std::shared_ptr<const Model> model);
  // Camera glyphs for `layer_depths_mm` x `views` (angles in the upright frame) and the up
  // arrow; empty vectors clear the glyphs.
  void SetCoverage(const std::vector<double>& layer_depths_mm, const std::vector<ViewAngles>& views,
                   const Eigen::Matrix3d& upright_from_model);
  // Highlights the glyph of `record` and looks at the model through that template's camera.
  void ShowTemplateCamera(const TemplateRecord& record, const PinholeCamera& camera,
                          const std::vector<double>& layer_depths_mm);
  void ClearHighlight();
  // A camera cone per ground-truth instance of a loaded frame, among the template cameras: white
  // when the envelope covers it, red when not. Instances of objects without templates are left
  // out; an empty list clears them.
  void SetGroundTruthViews(const std::vector<GroundTruthCoverage>& coverage);
  int ground_truth_view_count() const { return static_cast<int>(ground_truth_props_.size()); }
  // The capture's point cloud around `detection` and the detected mesh, in the object's model
  // frame, seen from the capture camera's position; the coverage glyphs are hidden meanwhile.
  void ShowDetection(const Capture& capture, const ArchiveObject& object,
                     const Detection& detection);
  void ClearDetection();

  int coverage_glyph_count() const { return coverage_glyphs_; }
  bool has_highlight() const { return highlight_ != nullptr; }
  bool has_up_arrow() const { return up_arrow_ != nullptr; }
  bool has_detection() const { return !detection_props_.empty(); }
  int detection_cloud_points() const { return detection_cloud_points_; }

 public slots:
  void ResetCamera();
  void SetCoverageVisible(bool visible);
  void SetSphereVisible(bool visible);
  void Render();

 private:
  void RemoveModelActors();
  // Puts the VTK camera at `cam_from_model`'s pose with `camera`'s vertical field of view; the
  // clipping range keeps `depth_margin_mm` around the sphere centre.
  void LookThrough(const Pose& cam_from_model, const PinholeCamera& camera, const Sphere& sphere,
                   double depth_margin_mm);
  // Looks at the sphere centre from `cam_from_model`'s camera position, framing `fit_radius_mm`.
  void LookAtFrom(const Pose& cam_from_model, const Sphere& sphere, double fit_radius_mm);
  void ShowCoverageActors(bool visible);

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkOrientationMarkerWidget> orientation_;
  std::shared_ptr<const Model> model_;
  std::vector<vtkSmartPointer<vtkProp>> model_props_;
  vtkSmartPointer<vtkActor> sphere_;
  vtkSmartPointer<vtkActor> coverage_;
  vtkSmartPointer<vtkActor> up_arrow_;
  Eigen::Matrix3d upright_from_model_ = Eigen::Matrix3d::Identity();
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkActor> highlight_;
  std::vector<vtkSmartPointer<vtkProp>> detection_props_;
  std::vector<vtkSmartPointer<vtkProp>> ground_truth_props_;
  double nearest_layer_mm_ = 0.0;  // of the coverage shown; 0 without
  int detection_cloud_points_ = 0;
  int coverage_glyphs_ = 0;
  double coverage_radius_mm_ = 0.0;  // outermost glyph shell around the sphere centre
  bool coverage_visible_ = true;
  bool sphere_visible_ = true;
};

}  // namespace layermod::ui
