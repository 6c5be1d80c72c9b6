// SPDX-License-Identifier: MIT
#pragma once

#include <vtkSmartPointer.h>

#include <Eigen/Core>
#include <vector>

#include "geometry/sphere.h"
#include "geometry/views.h"
#include "mesh/model.h"

class vtkActor;
class vtkAxesActor;
class vtkPolyData;
class vtkScalarBarActor;

namespace layermod::ui {

// Builders for the 3D view's actors (VTK pipelines only; no widget state). Everything is in model
// millimetres.

// An actor drawing `data` through a plain poly-data mapper.
vtkSmartPointer<vtkActor> ActorFor(vtkPolyData* data);

// The mesh with its vertex colours when present (grey otherwise). No vertex normals: the view
// shades per face, as CAD parts have sharp edges.
vtkSmartPointer<vtkPolyData> MeshPolyData(const Model& model);
vtkSmartPointer<vtkActor> MakeMeshActor(const Model& model);
// Translucent circumscribing sphere with a faint wireframe so its outline reads on any mesh.
vtkSmartPointer<vtkActor> MakeSphereActor(const Sphere& sphere);
vtkSmartPointer<vtkActor> MakeCentreMarker(const Sphere& sphere);
// Model axes at the model origin (X red, Y green, Z blue), `length_mm` long.
vtkSmartPointer<vtkAxesActor> MakeAxesActor(double length_mm);

// Where camera glyphs are drawn: every layer on its own shell around the sphere centre, with the
// shell radius proportional to the layer depth and the nearest layer at kNearestShellRadii radii,
// so the coverage stays visible next to the model whatever the real distances are.
// Views are angles in the upright frame of the training profile (geometry/up_axis.h); the glyphs
// are drawn in the model frame.
inline constexpr double kNearestShellRadii = 2.5;
double ShellRadiusMm(const Sphere& sphere, double depth_mm, double nearest_depth_mm);
Eigen::Vector3d GlyphPosition(const Sphere& sphere, const Eigen::Matrix3d& upright_from_model,
                              const ViewAngles& view, double depth_mm, double nearest_depth_mm);

// One cone per distinct camera direction and layer, pointing at the sphere centre, coloured by
// layer depth (the colour map MakeDepthScalarBar shows). Null when there is nothing to draw.
// `glyph_count` receives the number of cones.
vtkSmartPointer<vtkActor> MakeCoverageActor(const Sphere& sphere,
                                            const Eigen::Matrix3d& upright_from_model,
                                            const std::vector<double>& layer_depths_mm,
                                            const std::vector<ViewAngles>& views, int* glyph_count);
vtkSmartPointer<vtkScalarBarActor> MakeDepthScalarBar(vtkActor* coverage);

// A yellow arrow from the sphere centre along the model's up direction (the training profile's
// up axis), reaching just past the sphere.
vtkSmartPointer<vtkActor> MakeUpArrowActor(const Sphere& sphere,
                                           const Eigen::Matrix3d& upright_from_model);

// A larger bright cone at `position` pointing at the centre, plus the line of sight; yellow for
// the selected template, other colours for ground-truth cameras.
vtkSmartPointer<vtkActor> MakeHighlightActor(const Sphere& sphere, const Eigen::Vector3d& position,
                                             const Eigen::Vector3d& rgb = {1.0, 0.9, 0.1});

}  // namespace layermod::ui
