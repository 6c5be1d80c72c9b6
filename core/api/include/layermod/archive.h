// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <layermod/camera.h>

namespace layermod {
class TemplateArchive;
}

namespace layermod::api {

// One object of an archive.
struct ArchiveObjectInfo {
  std::int32_t obj_id = 0;
  std::string name;
  double diameter_mm = 0.0;
  std::vector<double> layer_depths_mm;  // layer index -> camera distance the layer was trained at
  std::size_t templates = 0;
};

// A loaded *.layermod template archive. A cheap handle: copies share the same immutable
// templates, and so does every Detector built from it (nothing is copied). Immutable, so one
// Archive may be used from any number of threads.
class Archive {
 public:
  // Reads and validates a *.layermod file. Throws IoError / FormatError naming the file and the
  // problem (never crashes on damaged bytes).
  static Archive Load(const std::filesystem::path& path);

  // Writes the archive atomically (temporary file + rename). Throws IoError.
  void Save(const std::filesystem::path& path) const;

  Camera camera() const;  // every template was rendered with these intrinsics
  std::vector<ArchiveObjectInfo> objects() const;
  std::size_t template_count() const;
  // What `layermod inspect --json` prints: manifest, camera, per-layer template statistics.
  std::string InfoJson(int indent = 2) const;

 private:
  friend struct ArchiveAccess;  // the facade's own access to the core type
  explicit Archive(std::shared_ptr<const TemplateArchive> archive);
  std::shared_ptr<const TemplateArchive> archive_;
};

}  // namespace layermod::api
