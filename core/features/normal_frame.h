// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace layermod {

// The frame a normal is expressed in.
// - kCamera: the camera's, as in LineMOD and in archives of format 2 and older.
// - kViewingRay: each pixel's own frame, the camera frame turned by the smallest rotation that
//   takes the pixel's viewing ray to the optical axis. A part seen off the image centre then gives
//   the normals it gives at the centre with the same view of it: in the camera frame they are
//   turned by the angle between the ray and the axis (up to about 35 degrees at a VGA Kinect's
//   corners), which moves many of them into a neighbouring quantization bin of the template's.
enum class NormalFrame { kCamera, kViewingRay };

// "camera" / "viewing_ray", as archives and profiles spell them.
std::string_view NormalFrameName(NormalFrame frame);
std::optional<NormalFrame> NormalFrameFromName(std::string_view name);

}  // namespace layermod
