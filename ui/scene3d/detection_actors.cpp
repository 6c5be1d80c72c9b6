// SPDX-License-Identifier: MIT
#include "ui/scene3d/detection_actors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include "ui/scene3d/scene_actors.h"

namespace layermod::ui {
namespace {

// Every second pixel in each direction: a quarter of the points, the same look.
constexpr int kPixelStep = 2;

}  // namespace

vtkSmartPointer<vtkActor> MakeCaptureCloudActor(const Capture& capture, const Pose& cam_from_model,
                                                const Sphere& sphere, double keep_radius_mm,
                                                int* point_count) {
  *point_count = 0;
  if (capture.depth_mm.empty()) return nullptr;
  const Pose model_from_cam = cam_from_model.Inverse();
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetNumberOfComponents(3);
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (int y = 0; y < capture.depth_mm.rows; y += kPixelStep) {
    for (int x = 0; x < capture.depth_mm.cols; x += kPixelStep) {
      const float depth_mm = capture.depth_mm.at<float>(y, x);
      if (depth_mm <= 0.0f) continue;
      const Eigen::Vector3d in_model =
          model_from_cam * capture.camera.Backproject(Eigen::Vector2d(x, y), depth_mm);
      if ((in_model - sphere.centre).norm() > keep_radius_mm) continue;
      const cv::Vec3b bgr = capture.color.at<cv::Vec3b>(y, x);
      const vtkIdType id = points->InsertNextPoint(in_model.data());
      colors->InsertNextTuple3(bgr[2], bgr[1], bgr[0]);
      vertices->InsertNextCell(1, &id);
    }
  }
  *point_count = static_cast<int>(points->GetNumberOfPoints());
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetVerts(vertices);
  data->GetPointData()->SetScalars(colors);
  auto actor = ActorFor(data);
  actor->GetMapper()->SetColorModeToDirectScalars();
  actor->GetProperty()->SetPointSize(3.0f);
  actor->GetProperty()->SetLighting(false);
  return actor;
}

vtkSmartPointer<vtkActor> MakeDetectedModelActor(const RenderMesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const Eigen::Vector3f& p : mesh.positions) points->InsertNextPoint(p.x(), p.y(), p.z());
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& triangle : mesh.triangles) {
    const vtkIdType ids[3] = {triangle[0], triangle[1], triangle[2]};
    triangles->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(triangles);
  auto actor = ActorFor(data);
  actor->GetProperty()->SetColor(0.2, 0.95, 0.3);
  actor->GetProperty()->SetOpacity(0.45);
  actor->GetProperty()->SetInterpolationToFlat();
  return actor;
}

}  // namespace layermod::ui
