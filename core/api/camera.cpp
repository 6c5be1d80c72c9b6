// SPDX-License-Identifier: MIT
#include <layermod/camera.h>

#include "api/archive_access.h"
#include "geometry/camera.h"

namespace layermod::api {

void Camera::Validate() const { ToCore(*this).Validate(); }

Camera Camera::FromJson(const std::filesystem::path& path) {
  return FromCore(LoadCameraJson(path));
}

}  // namespace layermod::api
