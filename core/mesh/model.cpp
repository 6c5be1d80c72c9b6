// SPDX-License-Identifier: MIT
#include "util/quoted.h"
#include "mesh/model.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <OpenMesh/Core/System/omstream.hh>
#include <assimp/Importer.hpp>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

constexpr double kMinTriangleAreaMm2 = 1e-12;
constexpr double kMetreScaleDiameterMm = 5.0;        // a part loaded as mm but this small: metres?
constexpr double kMillimetreScaleDiameterMm = 20e3;  // loaded as m but 20 m across: mm?
constexpr char kOriginWarningMarker[] = "origin is far from";

std::string FormatMm(double value_mm) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(std::abs(value_mm) < 10.0 ? 3 : 1) << value_mm << " mm";
  return out.str();
}

// Triangles with merged vertices, in mm, before they become an OpenMesh mesh.
struct TriangleSoup {
  std::vector<Eigen::Vector3d> positions;
  std::vector<OpenMesh::Vec3uc> colors;
  std::vector<std::array<int, 3>> triangles;
  bool has_colors = false;
};

void CheckReadableFile(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) throw IoError(Quoted(path) + ": no such file");
  if (ec) throw IoError(Quoted(path) + ": " + ec.message());
  if (fs::is_directory(status)) throw IoError(Quoted(path) + ": is a directory, not a mesh file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw IoError(Quoted(path) + ": cannot open for reading");
}

// 64-bit FNV-1a of the file bytes as 16 hex digits: identifies the model an archive was made from.
std::string HashFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(Quoted(path) + ": cannot open for reading");
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  std::size_t total = 0;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto count = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < count; ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 0x100000001b3ULL;
    }
    total += count;
  }
  if (in.bad()) throw IoError(Quoted(path) + ": read error");
  if (total == 0) throw FormatError(Quoted(path) + ": file is empty");
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

// Checked on the raw import: post-processing (vertex joining, degenerate search) is undefined
// on NaN, and a point cloud deserves a clearer word than assimp's validation message.
void CheckRawScene(const aiScene& scene, const fs::path& path, std::size_t max_triangles) {
  std::size_t triangles = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw FormatError(Quoted(path) + ": vertex " + std::to_string(v) +
                          " has a non-finite coordinate (NaN or infinity)");
      }
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      if (mesh.mFaces[f].mNumIndices >= 3) triangles += mesh.mFaces[f].mNumIndices - 2;
    }
  }
  if (triangles == 0) {
    throw FormatError(Quoted(path) + ": contains no triangles (points or lines only?)");
  }
  if (triangles > max_triangles) {
    throw FormatError(Quoted(path) + ": " + std::to_string(triangles) +
                      " triangles, more than the limit of " + std::to_string(max_triangles) +
                      "; decimate the mesh first");
  }
}

const aiScene* ImportScene(Assimp::Importer& importer, const fs::path& path,
                           std::size_t max_triangles) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  importer.SetPropertyBool(AI_CONFIG_PP_FD_REMOVE, true);
  // Assimp's area test uses an absolute threshold in file units, which would eat the small
  // triangles of metre-scale models; zero-area faces are dropped here in mm instead.
  importer.SetPropertyBool(AI_CONFIG_PP_FD_CHECKAREA, false);
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  if (scene == nullptr) {
    throw FormatError(Quoted(path) + ": cannot read as a mesh: " + importer.GetErrorString());
  }
  CheckRawScene(*scene, path, max_triangles);
  // Validation (index ranges, ...) before any step that would trust the data.
  if (importer.ApplyPostProcessing(aiProcess_ValidateDataStructure) == nullptr) {
    throw FormatError(Quoted(path) + ": invalid mesh data: " + importer.GetErrorString());
  }
  scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                       aiProcess_FindDegenerates | aiProcess_SortByPType);
  if (scene == nullptr) {
    throw FormatError(Quoted(path) + ": cannot process the mesh: " + importer.GetErrorString());
  }
  return scene;
}

struct PositionHash {
  std::size_t operator()(const Eigen::Vector3d& p) const {
    std::uint64_t h = 0;
    for (int i = 0; i < 3; ++i) {
      h ^= std::bit_cast<std::uint64_t>(p[i] + 0.0) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return static_cast<std::size_t>(h);
  }
};
struct PositionEqual {
  bool operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const { return a == b; }
};
using PositionIndex = std::unordered_map<Eigen::Vector3d, int, PositionHash, PositionEqual>;

OpenMesh::Vec3uc ToByteColor(const aiColor4D& c) {
  auto channel = [](float value) {
    return static_cast<unsigned char>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
  };
  return {channel(c.r), channel(c.g), channel(c.b)};
}

// Vertices at exactly the same position are merged across the whole scene: STL and per-face
// attributes split them, and the mesh must be connected for normals and cleaning.
void AppendMesh(const aiMesh& mesh, const Eigen::Affine3d& to_mm, const fs::path& path,
                PositionIndex& index, TriangleSoup& soup) {
  const bool colored = mesh.HasVertexColors(0);
  soup.has_colors = soup.has_colors || colored;
  std::vector<int> remap(mesh.mNumVertices);
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& raw = mesh.mVertices[v];
    const Eigen::Vector3d p = to_mm * Eigen::Vector3d(raw.x, raw.y, raw.z);
    if (!p.allFinite()) {
      throw FormatError(Quoted(path) + ": node transform gives non-finite vertices");
    }
    const auto [it, inserted] = index.try_emplace(p, static_cast<int>(soup.positions.size()));
    if (inserted) {
      soup.positions.push_back(p);
      soup.colors.push_back(colored ? ToByteColor(mesh.mColors[0][v])
                                    : OpenMesh::Vec3uc(kDefaultGrey, kDefaultGrey, kDefaultGrey));
    }
    remap[v] = it->second;
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    const std::array<int, 3> tri = {remap[face.mIndices[0]], remap[face.mIndices[1]],
                                    remap[face.mIndices[2]]};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
    const Eigen::Vector3d& a = soup.positions[tri[0]];
    const double area = 0.5 * (soup.positions[tri[1]] - a).cross(soup.positions[tri[2]] - a).norm();
    if (area < kMinTriangleAreaMm2) continue;
    soup.triangles.push_back(tri);
  }
}

Eigen::Affine3d ToEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d matrix;
  matrix << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
      m.d3, m.d4;
  return Eigen::Affine3d(matrix);
}

// Walks the node tree so that every mesh instance lands with its accumulated transform.
TriangleSoup CollectTriangles(const aiScene& scene, double mm_per_unit, const fs::path& path) {
  TriangleSoup soup;
  PositionIndex index;
  if (scene.mRootNode == nullptr) return soup;
  std::vector<std::pair<const aiNode*, Eigen::Affine3d>> stack;
  stack.emplace_back(scene.mRootNode, Eigen::Affine3d(Eigen::Scaling(mm_per_unit)));
  while (!stack.empty()) {
    const auto [node, parent] = stack.back();
    stack.pop_back();
    const Eigen::Affine3d transform = parent * ToEigen(node->mTransformation);
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      AppendMesh(*scene.mMeshes[node->mMeshes[i]], transform, path, index, soup);
    }
    for (unsigned i = 0; i < node->mNumChildren; ++i) {
      stack.emplace_back(node->mChildren[i], transform);
    }
  }
  return soup;
}

// OpenMesh reports non-manifold faces on its error stream; the core must not print, and the
// faces are kept anyway (see AddFaces).
class QuietOpenMesh {
 public:
  QuietOpenMesh() : was_enabled_(omerr().is_enabled()) { omerr().disable(); }
  ~QuietOpenMesh() {
    if (was_enabled_) omerr().enable();
  }
  QuietOpenMesh(const QuietOpenMesh&) = delete;
  QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

 private:
  bool was_enabled_;
};

// Non-manifold or inconsistently oriented triangles cannot join the half-edge structure; they
// get their own copies of their vertices, so that renders still show them.
void AddFaces(const TriangleSoup& soup, const std::vector<TriMesh::VertexHandle>& handles,
              TriMesh& mesh) {
  const QuietOpenMesh quiet;
  std::size_t split = 0;
  for (const auto& tri : soup.triangles) {
    if (mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid()) continue;
    std::array<TriMesh::VertexHandle, 3> copies;
    for (int k = 0; k < 3; ++k) {
      copies[k] = mesh.add_vertex(mesh.point(handles[tri[k]]));
      mesh.set_color(copies[k], mesh.color(handles[tri[k]]));
    }
    mesh.add_face(copies[0], copies[1], copies[2]);
    ++split;
  }
  if (split > 0) LogDebug(std::to_string(split) + " non-manifold triangles kept as separate faces");
}

void RemoveIsolatedVertices(TriMesh& mesh) {
  mesh.request_vertex_status();
  bool any = false;
  for (const auto vh : mesh.vertices()) {
    if (mesh.is_isolated(vh)) {
      mesh.delete_vertex(vh, false);
      any = true;
    }
  }
  if (any) mesh.garbage_collection();
  mesh.release_vertex_status();
}

TriMesh BuildMesh(const TriangleSoup& soup) {
  TriMesh mesh;
  std::vector<TriMesh::VertexHandle> handles(soup.positions.size());
  std::vector<bool> used(soup.positions.size(), false);
  for (const auto& tri : soup.triangles) {
    for (int k : tri) used[k] = true;
  }
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    if (!used[i]) continue;
    const Eigen::Vector3d& p = soup.positions[i];
    handles[i] = mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z()));
    mesh.set_color(handles[i], soup.colors[i]);
  }
  AddFaces(soup, handles, mesh);
  RemoveIsolatedVertices(mesh);
  mesh.update_face_normals();
  mesh.update_vertex_normals();
  return mesh;
}

void SetGeometry(Model& model) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(model.mesh.n_vertices());
  for (const auto vh : model.mesh.vertices()) {
    const auto& p = model.mesh.point(vh);
    points.emplace_back(p[0], p[1], p[2]);
  }
  model.sphere = MinimalEnclosingSphere(points);
  model.bbox_min = model.bbox_max = points.front();
  for (const auto& p : points) {
    model.bbox_min = model.bbox_min.cwiseMin(p);
    model.bbox_max = model.bbox_max.cwiseMax(p);
  }
}

void CheckNotDegenerate(const Model& model) {
  const Eigen::Vector3d extent = model.bbox_max - model.bbox_min;
  const double largest = extent.maxCoeff();
  const int non_zero = (extent.array() > 1e-9 * std::max(largest, 1.0)).count();
  // A flat plate is a valid (thin) part; a line or a point is not.
  if (model.sphere.radius <= 0.0 || non_zero < 2) {
    throw FormatError(Quoted(model.source) +
                      ": degenerate mesh (all vertices on a line or at one point)");
  }
}

void AddWarning(Model& model, std::string text) {
  LogWarning(text);
  model.warnings.push_back(std::move(text));
}

void AddWarnings(Model& model) {
  const double diameter_mm = model.DiameterMm();
  if (OriginFarFromCentre(model)) {
    AddWarning(model, Quoted(model.source) + ": model " + kOriginWarningMarker + " its centre (" +
                          FormatMm(model.sphere.centre.norm()) + " away, radius " +
                          FormatMm(model.sphere.radius) +
                          "); poses refer to the origin, consider re-centring");
  }
  if (model.source_units == LengthUnit::kMillimetre && diameter_mm < kMetreScaleDiameterMm) {
    AddWarning(model, Quoted(model.source) + ": model is only " + FormatMm(diameter_mm) +
                          " across; it looks like metres; use units m");
  }
  if (model.source_units == LengthUnit::kMetre && diameter_mm > kMillimetreScaleDiameterMm) {
    AddWarning(model, Quoted(model.source) + ": model is " + FormatMm(diameter_mm) +
                          " across when read as metres; it looks like millimetres; use units mm");
  }
}

}  // namespace

void LoadModelOptions::Validate() const {
  if (max_triangles == 0) throw Error("load model: max_triangles must be positive");
}

Model LoadModel(const fs::path& path, const LoadModelOptions& options) {
  options.Validate();
  CheckReadableFile(path);
  Model model;
  model.source = path;
  model.source_units = options.units;
  model.hash = HashFile(path);

  Assimp::Importer importer;
  const aiScene* scene = ImportScene(importer, path, options.max_triangles);
  const TriangleSoup soup = CollectTriangles(*scene, MillimetresPer(options.units), path);
  if (soup.triangles.empty()) {
    throw FormatError(Quoted(path) + ": degenerate mesh (no triangle has a non-zero area)");
  }
  model.mesh = BuildMesh(soup);
  model.has_vertex_colors = soup.has_colors;
  SetGeometry(model);
  CheckNotDegenerate(model);
  AddWarnings(model);
  return model;
}

bool OriginFarFromCentre(const Model& model) {
  return model.sphere.centre.norm() > kOriginWarningFraction * model.sphere.radius;
}

void RecentreOnSphere(Model& model) {
  const Eigen::Vector3d centre = model.sphere.centre;
  const TriMesh::Point shift(centre.x(), centre.y(), centre.z());
  for (const auto vh : model.mesh.vertices()) model.mesh.point(vh) -= shift;
  model.sphere.centre.setZero();
  model.bbox_min -= centre;
  model.bbox_max -= centre;
  std::erase_if(model.warnings, [](const std::string& warning) {
    return warning.find(kOriginWarningMarker) != std::string::npos;
  });
}

RenderMesh ToRenderMesh(const Model& model) {
  const TriMesh& mesh = model.mesh;
  // Dense indices even if the caller deleted elements without collecting the garbage.
  std::vector<std::uint32_t> index(mesh.n_vertices(), 0);
  std::uint32_t next = 0;
  for (const auto vh : mesh.vertices()) index[vh.idx()] = next++;
  RenderMesh render;
  render.positions.reserve(mesh.n_vertices());
  render.colors.reserve(mesh.n_vertices());
  const Eigen::Vector3f grey = Eigen::Vector3f::Constant(kDefaultGrey / 255.0f);
  for (const auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    render.positions.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]),
                                  static_cast<float>(p[2]));
    const auto& c = mesh.color(vh);
    render.colors.push_back(model.has_vertex_colors ? Eigen::Vector3f(c[0], c[1], c[2]) / 255.0f
                                                    : grey);
  }
  render.triangles.reserve(mesh.n_faces());
  for (const auto fh : mesh.faces()) {
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (const auto vh : mesh.fv_range(fh)) {
      if (k < 3) tri[k++] = index[vh.idx()];
    }
    render.triangles.push_back(tri);
  }
  return render;
}

}  // namespace layermod
