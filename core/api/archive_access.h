// SPDX-License-Identifier: MIT
// Internal: how the facade reaches the core types behind the public handles.
#pragma once

#include <layermod/archive.h>
#include <layermod/camera.h>

#include <memory>

#include "geometry/camera.h"
#include "templates/archive.h"

namespace layermod::api {

struct ArchiveAccess {
  static Archive Wrap(std::shared_ptr<const TemplateArchive> archive) {
    return Archive(std::move(archive));
  }
  static const std::shared_ptr<const TemplateArchive>& Core(const Archive& archive) {
    return archive.archive_;
  }
};

inline PinholeCamera ToCore(const Camera& camera) {
  return {camera.fx, camera.fy, camera.cx, camera.cy, camera.width, camera.height};
}

inline Camera FromCore(const PinholeCamera& camera) {
  return {camera.fx, camera.fy, camera.cx, camera.cy, camera.width, camera.height};
}

}  // namespace layermod::api
