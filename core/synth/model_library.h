// SPDX-License-Identifier: MIT
#pragma once

// The object models a synthetic dataset is built from: a BOP models folder.

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

#include "dataset/models_info.h"
#include "geometry/sphere.h"
#include "mesh/render_mesh.h"

namespace layermod {

struct SynthModel {
  std::int32_t obj_id = 0;
  std::filesystem::path path;  // the source file
  RenderMesh mesh;             // mm, model frame
  Sphere sphere;               // circumscribing sphere, model frame
  ModelInfo info;              // from the folder's models_info.json, else computed from the mesh
};

// The obj_NNNNNN.ply files of a BOP models folder, by object id. Throws IoError when the folder
// does not exist or holds no such file.
std::map<std::int32_t, std::filesystem::path> ListModelFiles(
    const std::filesystem::path& models_dir);

// The model files of a run: a BOP models folder (ListModelFiles), or a single PLY file that
// then is object `obj_ids` (which must name exactly one id). Throws Error/IoError.
std::map<std::int32_t, std::filesystem::path> ModelFilesFor(
    const std::filesystem::path& models, const std::vector<std::int32_t>& obj_ids);

// Loads the models `ids` of `files` (in parallel). Their ModelInfo comes from
// `models_dir`/models_info.json when it lists the object (diameter, symmetries), else from the mesh
// (exact diameter, bounding box, no symmetry). Throws Error for an id without a file, and the mesh
// or JSON readers' IoError/FormatError.
std::map<std::int32_t, SynthModel> LoadSynthModels(
    const std::filesystem::path& models_dir,
    const std::map<std::int32_t, std::filesystem::path>& files,
    const std::vector<std::int32_t>& ids);

// BOP model information computed from a mesh: exact diameter and bounding box.
ModelInfo ComputeModelInfo(std::int32_t obj_id, const RenderMesh& mesh);

}  // namespace layermod
