// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
// OpenMesh's VectorT leaves its values uninitialised by design; GCC 12 at -O3 then flags every
// add_vertex() on a mesh with colours (-Wmaybe-uninitialized inside OpenMesh's property code).
// The pragma must surround the include, where the templates are defined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/sphere.h"
#include "geometry/units.h"
#include "mesh/render_mesh.h"

namespace layermod {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  using Color = OpenMesh::Vec3uc;
  VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Color);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

struct LoadModelOptions {
  LengthUnit units = LengthUnit::kMillimetre;  // units of the file; converted to mm on load
  // Larger meshes are refused (decimate them first): they would make training crawl.
  std::size_t max_triangles = 20'000'000;
  // The file is read in a child process, so that a reader crash or hang on a hostile file is an
  // error, not the end of the program (see MeshImportOptions).
  bool isolate_import = true;
  std::chrono::seconds import_timeout{300};

  void Validate() const;  // throws Error
};

// Grey used for meshes without vertex colours.
inline constexpr unsigned char kDefaultGrey = 180;

// A cleaned CAD model in millimetres with its circumscribing sphere.
struct Model {
  TriMesh mesh;
  std::filesystem::path source;
  std::string hash;  // hex digest of the source file bytes
  LengthUnit source_units = LengthUnit::kMillimetre;
  bool has_vertex_colors = false;
  Sphere sphere;  // exact minimal enclosing sphere of the vertices (mm)
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_max = Eigen::Vector3d::Zero();
  std::vector<std::string> warnings;  // origin far from centre, metre-scale guess, ...

  double DiameterMm() const { return 2.0 * sphere.radius_mm; }
};

// Loads any mesh assimp reads (PLY, STL, OBJ, OFF, glTF, ...), keeps vertex colours, merges
// duplicate vertices, drops degenerate faces, computes normals, converts to mm and computes the
// sphere. Throws IoError (missing/unreadable) or FormatError (unsupported, empty, non-finite,
// degenerate) naming the file.
Model LoadModel(const std::filesystem::path& path, const LoadModelOptions& options = {});

// Distance from the model origin to the sphere centre above which a warning is issued, as a
// fraction of the radius.
inline constexpr double kOriginWarningFraction = 0.25;
bool OriginFarFromCentre(const Model& model);

// Moves the model so that the sphere centre becomes the origin (sphere and bounding box follow)
// and drops the origin warning.
void RecentreOnSphere(Model& model);

// Flat copy for the rasterizer (grey where the mesh has no colours).
RenderMesh ToRenderMesh(const Model& model);

// Writes the mesh as binary little-endian PLY: x y z nx ny nz (float), red green blue (uchar),
// triangles (mm, normals as stored in the mesh). Atomic. Throws IoError.
void SaveModelPly(const std::filesystem::path& path, const TriMesh& mesh);

}  // namespace layermod
