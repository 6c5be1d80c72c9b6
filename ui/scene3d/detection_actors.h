// SPDX-License-Identifier: MIT
#pragma once

#include <vtkSmartPointer.h>

#include "geometry/pose.h"
#include "geometry/sphere.h"
#include "mesh/render_mesh.h"
#include "pipeline/detector.h"

class vtkActor;

namespace layermod::ui {

// Builders for showing a detection in the 3D view, in the detected object's model frame (so the
// loaded model, its sphere and axes stay where they are).

// The capture's depth pixels back-projected, moved into the model frame by the inverse of
// `cam_from_model`, kept within `keep_radius_mm` of the sphere centre, coloured from the capture.
// `point_count` receives the number of points. Null without depth.
vtkSmartPointer<vtkActor> MakeCaptureCloudActor(const Capture& capture, const Pose& cam_from_model,
                                                const Sphere& sphere, double keep_radius_mm,
                                                int* point_count);

// The detected object's mesh (as stored in the archive), translucent green, in its model frame.
vtkSmartPointer<vtkActor> MakeDetectedModelActor(const RenderMesh& mesh);

}  // namespace layermod::ui
