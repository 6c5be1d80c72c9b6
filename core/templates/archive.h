// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "geometry/camera.h"
#include "geometry/sphere.h"
#include "mesh/render_mesh.h"
#include "templates/template_record.h"
#include "templates/training_profile.h"
#include "templates/view_clusters.h"

namespace layermod {

// Version 2 added the view tree (view_tree.bin); version 1 archives still load, their tree is
// built when they are read. Version 3 quantizes depth normals in each pixel's viewing-ray frame
// (the profile's features.normal_frame); older archives read as camera-frame ones and are
// matched on scenes quantized that way.
inline constexpr int kArchiveFormatVersion = 3;
inline constexpr int kOldestArchiveFormatVersion = 1;

// One object of an archive.
struct ArchiveObject {
  std::int32_t obj_id = 0;
  std::string name;
  std::string mesh_file;     // file name the object was trained from (no directory)
  std::string mesh_hash;     // hex digest of the mesh file bytes
  std::string units = "mm";  // units of the source mesh before conversion to mm
  Sphere sphere;             // circumscribing sphere in model mm
  double diameter_mm = 0.0;  // 2 * sphere.radius_mm
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_size = Eigen::Vector3d::Zero();
  std::vector<double> layer_depths_mm;  // layer_index -> depth
  TrainingProfile profile;
  RenderMesh mesh;  // the cleaned model (mm) for pose refinement, verification and overlays
};

// The readable manifest of a *.layermod file.
struct ArchiveManifest {
  int format_version = kArchiveFormatVersion;
  std::string tool_version;
  std::string created_utc;  // ISO 8601
  PinholeCamera camera;     // every template was rendered with this camera
  std::vector<ArchiveObject> objects;
};

// A loaded (or freshly trained) template set. Templates are stored in id order; records of one
// object and layer are contiguous, so queries return spans without copying.
class TemplateArchive {
 public:
  TemplateArchive() = default;
  // Builds the view tree: the views of every layer of at least kViewTreeTemplates templates are
  // clustered (templates/view_clusters.h).
  TemplateArchive(ArchiveManifest manifest, std::vector<TemplateRecord> templates);
  // With a stored view tree: one leader (a template id, or kNoViewCluster) per template, as
  // ViewLeaders() gives it. Throws FormatError when the tree does not fit the templates.
  TemplateArchive(ArchiveManifest manifest, std::vector<TemplateRecord> templates,
                  std::span<const std::uint32_t> view_leaders, double view_cluster_radius_deg);

  const ArchiveManifest& manifest() const { return manifest_; }
  const std::vector<TemplateRecord>& templates() const { return templates_; }
  const PinholeCamera& camera() const { return manifest_.camera; }

  const ArchiveObject& Object(std::int32_t obj_id) const;  // throws Error if absent
  std::span<const TemplateRecord> TemplatesOf(std::int32_t obj_id) const;
  std::span<const TemplateRecord> TemplatesOf(std::int32_t obj_id, int layer_index) const;

  // The view clusters of a layer, as indices into TemplatesOf(obj_id, layer_index); empty for
  // layers without a view tree (searched flat).
  std::span<const ViewCluster> ViewClustersOf(std::int32_t obj_id, int layer_index) const;
  std::size_t ViewClusterCount() const;  // over all layers
  // The view tree as the archive file stores it: for each template the id of its cluster's
  // representative, kNoViewCluster for templates in no cluster.
  std::vector<std::uint32_t> ViewLeaders() const;

 private:
  struct Range {
    std::int32_t obj_id;
    int layer_index;  // -1: the whole object
    std::size_t begin;
    std::size_t end;
    std::vector<ViewCluster> clusters;  // layers only
  };

  void BuildIndex();  // throws FormatError if records are not grouped by object and layer
  const Range* FindRange(std::int32_t obj_id, int layer_index) const;  // nullptr: none

  ArchiveManifest manifest_;
  std::vector<TemplateRecord> templates_;
  std::vector<Range> index_;
};

// Writes `archive` to `path` atomically (temporary file + rename). Throws IoError.
void WriteArchive(const std::filesystem::path& path, const TemplateArchive& archive);

// Reads and validates a *.layermod file (magic, version, sizes, checksums, value ranges).
// Throws IoError / FormatError naming the file and the problem; never crashes on bad bytes.
TemplateArchive ReadArchive(const std::filesystem::path& path);

// The same from bytes already in memory (`name` is used in messages). For tests and fuzzing.
TemplateArchive ReadArchiveBytes(std::string_view bytes, const std::string& name);

}  // namespace layermod
