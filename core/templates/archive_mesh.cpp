// SPDX-License-Identifier: MIT
#include "templates/archive_mesh.h"

#include <algorithm>
#include <cmath>

namespace layermod {
namespace {

// Sphere agreement tolerance: the sphere is recomputed from the same vertices, so it agrees to
// rounding; a unit mix-up or a moved origin is far beyond this.
constexpr double kSphereTolerance = 1e-3;

}  // namespace

bool ModelMatchesObject(const Model& model, const ArchiveObject& object) {
  if (!object.mesh_hash.empty() && model.hash != object.mesh_hash) return false;
  const double tolerance_mm = kSphereTolerance * std::max(1.0, object.sphere.radius_mm);
  return std::abs(model.sphere.radius_mm - object.sphere.radius_mm) <= tolerance_mm &&
         (model.sphere.centre - object.sphere.centre).norm() <= tolerance_mm;
}

std::optional<std::filesystem::path> MeshBesideArchive(const std::filesystem::path& archive_path,
                                                       const ArchiveObject& object) {
  if (object.mesh_file.empty()) return std::nullopt;
  // mesh_file is a bare name; never let an archive point outside its directory.
  const std::filesystem::path name = std::filesystem::path(object.mesh_file).filename();
  const std::filesystem::path candidate = archive_path.parent_path() / name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(candidate, error)) return std::nullopt;
  return candidate;
}

Model LoadModelForObject(const std::filesystem::path& mesh_path, const ArchiveObject& object) {
  LoadModelOptions options;
  options.units = object.units == "m" ? LengthUnit::kMetre : LengthUnit::kMillimetre;
  Model model = LoadModel(mesh_path, options);
  const double tolerance_mm = kSphereTolerance * std::max(1.0, object.sphere.radius_mm);
  if (object.sphere.centre.norm() <= tolerance_mm && model.sphere.centre.norm() > tolerance_mm) {
    RecentreOnSphere(model);
  }
  return model;
}

}  // namespace layermod
