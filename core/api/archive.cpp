// SPDX-License-Identifier: MIT
#include <layermod/archive.h>

#include "api/archive_access.h"
#include "api/archive_info.h"
#include "templates/archive.h"

namespace layermod::api {

Archive::Archive(std::shared_ptr<const TemplateArchive> archive) : archive_(std::move(archive)) {}

Archive Archive::Load(const std::filesystem::path& path) {
  return Archive(std::make_shared<const TemplateArchive>(ReadArchive(path)));
}

void Archive::Save(const std::filesystem::path& path) const { WriteArchive(path, *archive_); }

Camera Archive::camera() const { return FromCore(archive_->camera()); }

std::vector<ArchiveObjectInfo> Archive::objects() const {
  std::vector<ArchiveObjectInfo> objects;
  for (const ArchiveObject& object : archive_->manifest().objects) {
    objects.push_back({object.obj_id, object.name, object.diameter_mm, object.layer_depths_mm,
                       archive_->TemplatesOf(object.obj_id).size()});
  }
  return objects;
}

std::size_t Archive::template_count() const { return archive_->templates().size(); }

std::string Archive::InfoJson(int indent) const { return ArchiveInfoJson(*archive_).dump(indent); }

}  // namespace layermod::api
