// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>

#include "mesh/model.h"
#include "templates/archive.h"

namespace layermod {

// Whether `model` is the mesh `object` was trained from, with the same units and placement, so
// the archive's poses render it correctly.
bool ModelMatchesObject(const Model& model, const ArchiveObject& object);

// The object's mesh file (ArchiveObject::mesh_file) in the archive's directory, if it exists.
std::optional<std::filesystem::path> MeshBesideArchive(const std::filesystem::path& archive_path,
                                                       const ArchiveObject& object);

// Loads `mesh_path` as `object` was trained: in its units, re-centred when the archive's sphere
// sits at the origin but the file's does not. Throws like LoadModel.
Model LoadModelForObject(const std::filesystem::path& mesh_path, const ArchiveObject& object);

}  // namespace layermod
