// SPDX-License-Identifier: MIT
#include "ui/scene3d/scene_actors.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkAxesActor.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkLineSource.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <utility>

#include "geometry/pose.h"
#include "geometry/up_axis.h"
#include "pipeline/overlays.h"

namespace layermod::ui {
namespace {

// Glyph size as a fraction of its shell radius: the same apparent size on every shell.
constexpr double kGlyphFraction = 0.035;

Eigen::Vector3d ToCamera(const ViewAngles& view) {
  const double az = DegToRad(view.azimuth_deg);
  const double el = DegToRad(view.elevation_deg);
  return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

// Camera directions without the in-plane rolls (views are listed direction by direction).
std::vector<ViewAngles> DistinctDirections(const std::vector<ViewAngles>& views) {
  std::set<std::pair<long long, long long>> seen;
  std::vector<ViewAngles> directions;
  for (const ViewAngles& view : views) {
    const auto key = std::make_pair(std::llround(view.azimuth_deg * 1000.0),
                                    std::llround(view.elevation_deg * 1000.0));
    if (seen.insert(key).second) directions.push_back({view.azimuth_deg, view.elevation_deg, 0.0});
  }
  return directions;
}

vtkSmartPointer<vtkPolyData> CoveragePoints(const Sphere& sphere,
                                            const Eigen::Matrix3d& upright_from_model,
                                            const std::vector<double>& layer_depths_mm,
                                            const std::vector<ViewAngles>& directions) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto layers = vtkSmartPointer<vtkFloatArray>::New();
  layers->SetName("layer_index");
  auto aims = vtkSmartPointer<vtkDoubleArray>::New();
  aims->SetName("aim");
  aims->SetNumberOfComponents(3);
  const double nearest_mm = layer_depths_mm.front();
  for (std::size_t layer = 0; layer < layer_depths_mm.size(); ++layer) {
    for (const ViewAngles& direction : directions) {
      const Eigen::Vector3d at =
          GlyphPosition(sphere, upright_from_model, direction, layer_depths_mm[layer], nearest_mm);
      points->InsertNextPoint(at.data());
      layers->InsertNextValue(static_cast<float>(layer));
      // Towards the centre; the length is the glyph size (scale by vector).
      const Eigen::Vector3d aim = (sphere.centre - at) * kGlyphFraction;
      aims->InsertNextTuple(aim.data());
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->GetPointData()->SetScalars(layers);
  data->GetPointData()->SetVectors(aims);
  return data;
}

}  // namespace

vtkSmartPointer<vtkActor> ActorFor(vtkPolyData* data) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkPolyData> MeshPolyData(const Model& model) {
  const TriMesh& mesh = model.mesh;
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.n_vertices()));
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(mesh.n_vertices()));
  for (const auto vertex : mesh.vertices()) {
    const auto id = static_cast<vtkIdType>(vertex.idx());
    const auto& p = mesh.point(vertex);
    points->SetPoint(id, p[0], p[1], p[2]);
    const auto& c = mesh.color(vertex);
    colors->SetTuple3(id, c[0], c[1], c[2]);
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  for (const auto face : mesh.faces()) {
    vtkIdType ids[3];
    int corner = 0;
    for (const auto vertex : face.vertices()) ids[corner++] = static_cast<vtkIdType>(vertex.idx());
    triangles->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  if (model.has_vertex_colors) data->GetPointData()->SetScalars(colors);
  return data;
}

vtkSmartPointer<vtkActor> MakeMeshActor(const Model& model) {
  auto actor = ActorFor(MeshPolyData(model));
  auto* mapper = actor->GetMapper();
  mapper->SetScalarVisibility(model.has_vertex_colors);
  mapper->SetColorModeToDirectScalars();
  const double grey = kDefaultGrey / 255.0;
  actor->GetProperty()->SetColor(grey, grey, grey);
  // CAD parts have sharp edges that shared-vertex normals would smear: shade per face.
  actor->GetProperty()->SetInterpolationToFlat();
  actor->GetProperty()->SetSpecular(0.2);
  return actor;
}

vtkSmartPointer<vtkActor> MakeSphereActor(const Sphere& sphere) {
  auto source = vtkSmartPointer<vtkSphereSource>::New();
  source->SetCenter(sphere.centre.data());
  source->SetRadius(sphere.radius_mm);
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  source->Update();
  auto actor = ActorFor(source->GetOutput());
  actor->GetProperty()->SetColor(0.35, 0.65, 1.0);
  actor->GetProperty()->SetOpacity(0.15);
  actor->GetProperty()->SetEdgeVisibility(true);
  actor->GetProperty()->SetEdgeColor(0.45, 0.7, 1.0);
  actor->GetProperty()->SetLineWidth(0.5);
  return actor;
}

vtkSmartPointer<vtkActor> MakeCentreMarker(const Sphere& sphere) {
  auto source = vtkSmartPointer<vtkSphereSource>::New();
  source->SetCenter(sphere.centre.data());
  source->SetRadius(std::max(sphere.radius_mm * 0.03, 1e-3));
  source->Update();
  auto actor = ActorFor(source->GetOutput());
  actor->GetProperty()->SetColor(1.0, 0.2, 0.6);
  return actor;
}

vtkSmartPointer<vtkAxesActor> MakeAxesActor(double length_mm) {
  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  axes->SetTotalLength(length_mm, length_mm, length_mm);
  axes->SetShaftTypeToCylinder();
  axes->SetCylinderRadius(0.02);
  // Labels would be drawn as large as the corner marker's; the colours (X red, Y green, Z blue)
  // and the labelled corner marker say which is which.
  axes->AxisLabelsOff();
  return axes;
}

double ShellRadiusMm(const Sphere& sphere, double depth_mm, double nearest_depth_mm) {
  return kNearestShellRadii * sphere.radius_mm * depth_mm / nearest_depth_mm;
}

Eigen::Vector3d GlyphPosition(const Sphere& sphere, const Eigen::Matrix3d& upright_from_model,
                              const ViewAngles& view, double depth_mm, double nearest_depth_mm) {
  return sphere.centre + ShellRadiusMm(sphere, depth_mm, nearest_depth_mm) *
                             (upright_from_model.transpose() * ToCamera(view));
}

vtkSmartPointer<vtkActor> MakeUpArrowActor(const Sphere& sphere,
                                           const Eigen::Matrix3d& upright_from_model) {
  const Eigen::Vector3d up = UpDirectionInModel(upright_from_model);
  auto arrow = vtkSmartPointer<vtkArrowSource>::New();
  arrow->SetShaftRadius(0.025);
  arrow->SetTipRadius(0.07);
  arrow->SetTipLength(0.12);
  arrow->SetShaftResolution(16);
  arrow->SetTipResolution(16);
  // vtkArrowSource points along +X from the origin, one unit long.
  const double length_mm = 2.0 * sphere.radius_mm;
  const Eigen::Matrix3d along_up =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), up).toRotationMatrix();
  auto transform = vtkSmartPointer<vtkTransform>::New();
  vtkNew<vtkMatrix4x4> matrix;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, length_mm * along_up(r, c));
    matrix->SetElement(r, 3, sphere.centre[r]);
  }
  transform->SetMatrix(matrix);
  auto placed = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  placed->SetInputConnection(arrow->GetOutputPort());
  placed->SetTransform(transform);
  placed->Update();
  auto actor = ActorFor(placed->GetOutput());
  actor->GetProperty()->SetColor(1.0, 0.85, 0.1);
  actor->GetProperty()->SetAmbient(0.4);
  return actor;
}

vtkSmartPointer<vtkActor> MakeCoverageActor(const Sphere& sphere,
                                            const Eigen::Matrix3d& upright_from_model,
                                            const std::vector<double>& layer_depths_mm,
                                            const std::vector<ViewAngles>& views,
                                            int* glyph_count) {
  *glyph_count = 0;
  if (layer_depths_mm.empty() || views.empty()) return nullptr;
  auto cone = vtkSmartPointer<vtkConeSource>::New();
  cone->SetResolution(8);
  cone->SetHeight(1.0);
  cone->SetRadius(0.35);
  auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  const auto points =
      CoveragePoints(sphere, upright_from_model, layer_depths_mm, DistinctDirections(views));
  *glyph_count = static_cast<int>(points->GetNumberOfPoints());
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(cone->GetOutputPort());
  glyphs->SetVectorModeToUseVector();
  glyphs->SetScaleModeToScaleByVector();
  glyphs->SetColorModeToColorByScalar();
  glyphs->OrientOn();
  glyphs->Update();

  // One colour per layer, the same as the detection preview's layer legend and region overlay.
  const int count = static_cast<int>(layer_depths_mm.size());
  auto lookup = vtkSmartPointer<vtkLookupTable>::New();
  lookup->SetNumberOfTableValues(count);
  lookup->SetTableRange(-0.5, count - 0.5);
  for (int i = 0; i < count; ++i) {
    const cv::Scalar bgr = LayerColor(i, count);
    lookup->SetTableValue(i, bgr[2] / 255.0, bgr[1] / 255.0, bgr[0] / 255.0, 1.0);
    char label[32];
    std::snprintf(label, sizeof(label), "%.0f mm", layer_depths_mm[static_cast<std::size_t>(i)]);
    lookup->SetAnnotation(vtkVariant(static_cast<double>(i)), label);
  }
  auto actor = ActorFor(glyphs->GetOutput());
  auto* mapper = actor->GetMapper();
  mapper->SetLookupTable(lookup);
  mapper->SetScalarModeToUsePointData();
  mapper->UseLookupTableScalarRangeOn();
  return actor;
}

vtkSmartPointer<vtkScalarBarActor> MakeDepthScalarBar(vtkActor* coverage) {
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(coverage->GetMapper()->GetLookupTable());
  // Discrete: one swatch per layer, labelled with its depth.
  bar->SetTitle("layer depth");
  bar->DrawTickLabelsOff();
  bar->DrawAnnotationsOn();
  bar->SetMaximumNumberOfColors(
      static_cast<int>(coverage->GetMapper()->GetLookupTable()->GetNumberOfAvailableColors()));
  bar->SetMaximumWidthInPixels(90);
  bar->SetMaximumHeightInPixels(260);
  bar->SetPosition(0.88, 0.08);
  bar->SetWidth(0.1);
  bar->SetHeight(0.5);
  bar->GetTitleTextProperty()->SetFontSize(13);
  bar->GetLabelTextProperty()->SetFontSize(12);
  bar->UnconstrainedFontSizeOn();
  return bar;
}

vtkSmartPointer<vtkActor> MakeHighlightActor(const Sphere& sphere, const Eigen::Vector3d& position,
                                             const Eigen::Vector3d& rgb) {
  const Eigen::Vector3d aim = sphere.centre - position;
  const double size_mm = aim.norm() * kGlyphFraction * 2.5;
  auto cone = vtkSmartPointer<vtkConeSource>::New();
  cone->SetResolution(16);
  cone->SetHeight(size_mm);
  cone->SetRadius(size_mm * 0.4);
  cone->SetCenter(position.data());
  cone->SetDirection(aim.data());
  auto line = vtkSmartPointer<vtkLineSource>::New();
  line->SetPoint1(position.data());
  line->SetPoint2(sphere.centre.data());
  auto both = vtkSmartPointer<vtkAppendPolyData>::New();
  both->AddInputConnection(cone->GetOutputPort());
  both->AddInputConnection(line->GetOutputPort());
  both->Update();
  auto actor = ActorFor(both->GetOutput());
  actor->GetProperty()->SetColor(rgb.x(), rgb.y(), rgb.z());
  actor->GetProperty()->SetLineWidth(2.0);
  actor->GetProperty()->SetAmbient(0.5);
  return actor;
}

}  // namespace layermod::ui
