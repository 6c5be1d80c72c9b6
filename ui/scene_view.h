// SPDX-License-Identifier: MIT
#pragma once

#include <QVTKOpenGLNativeWidget.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

#include "geometry/camera.h"
#include "geometry/views.h"
#include "mesh/model.h"
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
  // Camera glyphs for `layer_depths_mm` x `views`; empty vectors clear them.
  void SetCoverage(const std::vector<double>& layer_depths_mm,
                   const std::vector<ViewAngles>& views);
  // Highlights the glyph of `record` and looks at the model through that template's camera.
  void ShowTemplateCamera(const TemplateRecord& record, const PinholeCamera& camera,
                          const std::vector<double>& layer_depths_mm);
  void ClearHighlight();

  int coverage_glyph_count() const { return coverage_glyphs_; }
  bool has_highlight() const { return highlight_ != nullptr; }

 public slots:
  void ResetCamera();
  void SetCoverageVisible(bool visible);
  void SetSphereVisible(bool visible);
  void Render();

 private:
  void RemoveModelActors();

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkOrientationMarkerWidget> orientation_;
  std::shared_ptr<const Model> model_;
  std::vector<vtkSmartPointer<vtkProp>> model_props_;
  vtkSmartPointer<vtkActor> sphere_;
  vtkSmartPointer<vtkActor> coverage_;
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkActor> highlight_;
  int coverage_glyphs_ = 0;
  bool coverage_visible_ = true;
  bool sphere_visible_ = true;
};

}  // namespace layermod::ui
