// SPDX-License-Identifier: MIT
#include "mesh/mesh_import.h"

#include <unistd.h>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <bit>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <unordered_map>
#include <utility>

#include "mesh/model.h"
#include "mesh/ply_header.h"
#include "util/error.h"
#include "util/log.h"
#include "util/quoted.h"
#include "util/subprocess.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

constexpr double kMinTriangleAreaMm2 = 1e-12;
constexpr std::array<unsigned char, 3> kGreyColor = {kDefaultGrey, kDefaultGrey, kDefaultGrey};
constexpr char kSoupMagic[8] = {'L', 'M', 'S', 'O', 'U', 'P', '0', '1'};

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

std::array<unsigned char, 3> ToByteColor(const aiColor4D& c) {
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
      soup.colors.push_back(colored ? ToByteColor(mesh.mColors[0][v]) : kGreyColor);
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

TriangleSoup ImportInProcess(const fs::path& path, const MeshImportOptions& options) {
  Assimp::Importer importer;
  const aiScene* scene = ImportScene(importer, path, options.max_triangles);
  return CollectTriangles(*scene, MillimetresPer(options.units), path);
}

template <typename T>
void AppendRaw(std::string& bytes, const T* data, std::size_t count) {
  bytes.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

template <typename T>
void ReadRaw(const std::string& bytes, std::size_t& offset, T* data, std::size_t count) {
  std::memcpy(data, bytes.data() + offset, count * sizeof(T));
  offset += count * sizeof(T);
}

std::string LastLine(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  const auto newline = text.rfind('\n');
  return newline == std::string::npos ? text : text.substr(newline + 1);
}

TriangleSoup SoupFromImporter(const ProcessResult& run, const fs::path& path,
                              const MeshImportOptions& options) {
  const std::string prefix = Quoted(path) + ": the mesh importer";
  if (run.timed_out) {
    throw FormatError(prefix + " took longer than " + std::to_string(options.timeout.count()) +
                      " s on this file and was stopped; it is malformed or far too large");
  }
  if (run.signal_number == SIGINT || run.signal_number == SIGTERM || run.signal_number == SIGHUP) {
    throw Error(prefix + " was interrupted (signal " + std::to_string(run.signal_number) + ")");
  }
  const std::string message = LastLine(run.err);
  if (run.signal_number == 0 && (run.exit_code == 0 || !message.empty())) {
    switch (run.exit_code) {
      case 0:
        return ParseSoup(run.out, path.string());
      case kImporterFormatError:
        throw FormatError(message);
      case kImporterIoError:
        throw IoError(message);
      case kImporterError:
        throw Error(message);
      default:
        break;  // 1 (a sanitizer's report) or anything else: a crash
    }
  }
  const std::string how = run.signal_number != 0 ? "signal " + std::to_string(run.signal_number)
                                                 : "exit status " + std::to_string(run.exit_code);
  throw FormatError(prefix + " crashed (" + how +
                    ") on this file; it is malformed or uses a variant that cannot be read");
}

}  // namespace

std::string SerializeSoup(const TriangleSoup& soup) {
  std::string bytes(kSoupMagic, sizeof(kSoupMagic));
  const std::uint64_t counts[2] = {soup.positions.size(), soup.triangles.size()};
  AppendRaw(bytes, counts, 2);
  bytes.push_back(soup.has_colors ? 1 : 0);
  for (const Eigen::Vector3d& p : soup.positions) AppendRaw(bytes, p.data(), 3);
  for (const auto& c : soup.colors) AppendRaw(bytes, c.data(), 3);
  for (const auto& t : soup.triangles) AppendRaw(bytes, t.data(), 3);
  return bytes;
}

TriangleSoup ParseSoup(const std::string& bytes, const std::string& name) {
  const std::size_t header = sizeof(kSoupMagic) + 2 * sizeof(std::uint64_t) + 1;
  if (bytes.size() < header || std::memcmp(bytes.data(), kSoupMagic, sizeof(kSoupMagic)) != 0) {
    throw FormatError(Quoted(name) + ": mesh import returned no mesh data");
  }
  std::size_t offset = sizeof(kSoupMagic);
  std::uint64_t counts[2];
  ReadRaw(bytes, offset, counts, 2);
  const std::uint64_t expected =
      header + counts[0] * (3 * sizeof(double) + 3) + counts[1] * 3 * sizeof(int);
  if (counts[0] > bytes.size() || counts[1] > bytes.size() || expected != bytes.size()) {
    throw FormatError(Quoted(name) + ": mesh import returned inconsistent mesh data");
  }
  TriangleSoup soup;
  soup.has_colors = bytes[offset++] != 0;
  soup.positions.resize(counts[0]);
  soup.colors.resize(counts[0]);
  soup.triangles.resize(counts[1]);
  for (Eigen::Vector3d& p : soup.positions) ReadRaw(bytes, offset, p.data(), 3);
  for (auto& c : soup.colors) ReadRaw(bytes, offset, c.data(), 3);
  for (auto& t : soup.triangles) {
    ReadRaw(bytes, offset, t.data(), 3);
    for (int index : t) {
      if (index < 0 || static_cast<std::uint64_t>(index) >= counts[0]) {
        throw FormatError(Quoted(name) + ": mesh import returned an out-of-range vertex index");
      }
    }
  }
  return soup;
}

namespace {

// In a CMake build tree (an ancestor of the executable holding CMakeCache.txt) the helper is in
// its app/ folder. Found at run time, so that the installed library carries no build path.
fs::path BuildTreeImporter(const fs::path& self_dir) {
  std::error_code ec;
  for (fs::path dir = self_dir; !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_regular_file(dir / "CMakeCache.txt", ec)) {
      const fs::path candidate = dir / "app" / kMeshImporterName;
      return fs::is_regular_file(candidate, ec) ? candidate : fs::path();
    }
    if (dir == dir.parent_path()) break;
  }
  return {};
}

}  // namespace

fs::path MeshImporterPath() {
  if (const char* env = std::getenv(kMeshImporterEnv); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  const fs::path self_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) return {};
  for (const fs::path& candidate :
       {self_dir / kMeshImporterName, self_dir / ".." / "libexec" / "layermod" / kMeshImporterName,
        fs::path(LAYERMOD_IMPORTER_INSTALL_PATH), fs::path(LAYERMOD_IMPORTER_PACKAGE_PATH)}) {
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  return BuildTreeImporter(self_dir);
}

TriangleSoup ImportTriangles(const fs::path& path, const MeshImportOptions& options) {
  if (!fs::is_regular_file(path)) throw IoError(Quoted(path) + ": no such file");
  CheckPlyHeader(path, options.max_triangles);
  const fs::path importer = options.isolate ? MeshImporterPath() : fs::path();
  if (importer.empty()) {
    if (options.isolate) {
      LogWarning(std::string(kMeshImporterName) + " not found (set " + kMeshImporterEnv +
                 "); reading " + Quoted(path) + " in this process");
    }
    return ImportInProcess(path, options);
  }
  const ProcessResult run =
      RunProcess({importer.string(), "--units", options.units == LengthUnit::kMetre ? "m" : "mm",
                  "--max-triangles", std::to_string(options.max_triangles), "--parent",
                  std::to_string(::getpid()), "--", path.string()},
                 options.timeout);
  return SoupFromImporter(run, path, options);
}

int ImporterExitCode(const Error& error) {
  if (dynamic_cast<const FormatError*>(&error) != nullptr) return kImporterFormatError;
  if (dynamic_cast<const IoError*>(&error) != nullptr) return kImporterIoError;
  return kImporterError;
}

}  // namespace layermod
