// SPDX-License-Identifier: MIT
#include "mesh/model.h"
#include "util/quoted.h"

#include <OpenMesh/Core/System/omstream.hh>

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

#include "mesh/mesh_import.h"
#include "util/atomic_file.h"
#include "util/error.h"
#include "util/log.h"

namespace layermod {
namespace fs = std::filesystem;
namespace {

constexpr double kMetreScaleDiameterMm = 5.0;        // a part loaded as mm but this small: metres?
constexpr double kMillimetreScaleDiameterMm = 20e3;  // loaded as m but 20 m across: mm?
constexpr char kOriginWarningMarker[] = "origin is far from";

std::string FormatMm(double value_mm) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(std::abs(value_mm) < 10.0 ? 3 : 1) << value_mm << " mm";
  return out.str();
}

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

// OpenMesh reports non-manifold faces on its error stream; the core must not print, and the
// faces are kept anyway (see AddFaces). The stream is one for the process and models load on
// several threads at once (synth), so it is silenced once and stays so: a switch turned back on
// after each load let one thread's report through while another was still loading.
void SilenceOpenMesh() {
  static const bool silenced = [] {
    omerr().disable();
    return true;
  }();
  (void)silenced;
}

// Non-manifold or inconsistently oriented triangles cannot join the half-edge structure; they
// get their own copies of their vertices, so that renders still show them.
void AddFaces(const TriangleSoup& soup, const std::vector<TriMesh::VertexHandle>& handles,
              TriMesh& mesh) {
  SilenceOpenMesh();
  std::size_t split = 0;
  for (const auto& tri : soup.triangles) {
    if (mesh.add_face(handles[tri[0]], handles[tri[1]], handles[tri[2]]).is_valid()) continue;
    std::array<TriMesh::VertexHandle, 3> copies;
    for (int k = 0; k < 3; ++k) {
      // Copies, not references: add_vertex may reallocate the arrays they point into.
      const TriMesh::Point point = mesh.point(handles[tri[k]]);
      const TriMesh::Color color = mesh.color(handles[tri[k]]);
      copies[k] = mesh.add_vertex(point);
      mesh.set_color(copies[k], color);
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
    const auto& c = soup.colors[i];
    mesh.set_color(handles[i], TriMesh::Color(c[0], c[1], c[2]));
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
  if (model.sphere.radius_mm <= 0.0 || non_zero < 2) {
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
    AddWarning(model,
               Quoted(model.source) + ": model " + kOriginWarningMarker + " its centre (" +
                   FormatMm(model.sphere.centre.norm()) + " away, radius " +
                   FormatMm(model.sphere.radius_mm) +
                   "); poses refer to the mesh's origin, as ground truth in the mesh's frame "
                   "(BOP) does; re-centring would make them refer to the centre instead");
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
  if (import_timeout.count() <= 0) throw Error("load model: import_timeout must be positive");
}

Model LoadModel(const fs::path& path, const LoadModelOptions& options) {
  options.Validate();
  CheckReadableFile(path);
  Model model;
  model.source = path;
  model.source_units = options.units;
  model.hash = HashFile(path);

  const TriangleSoup soup = ImportTriangles(
      path, {options.units, options.max_triangles, options.isolate_import, options.import_timeout});
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
  return model.sphere.centre.norm() > kOriginWarningFraction * model.sphere.radius_mm;
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
