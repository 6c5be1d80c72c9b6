// SPDX-License-Identifier: MIT
#include "templates/archive.h"

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

#include "util/error.h"

namespace layermod {
namespace {

std::string RunName(std::int32_t obj_id, int layer_index) {
  return "object " + std::to_string(obj_id) + " layer " + std::to_string(layer_index);
}

void CheckIdsAndObjects(const ArchiveManifest& manifest,
                        const std::vector<TemplateRecord>& templates) {
  std::set<std::int32_t> objects;
  for (const ArchiveObject& object : manifest.objects) objects.insert(object.obj_id);
  for (std::size_t i = 0; i < templates.size(); ++i) {
    if (templates[i].id != i) {
      throw FormatError("template " + std::to_string(i) + " has id " +
                        std::to_string(templates[i].id) + ": ids must be 0..n-1 in order");
    }
    if (!objects.contains(templates[i].obj_id)) {
      throw FormatError("template " + std::to_string(i) + " belongs to object " +
                        std::to_string(templates[i].obj_id) + ", which is not in the manifest");
    }
  }
}

}  // namespace

TemplateArchive::TemplateArchive(ArchiveManifest manifest, std::vector<TemplateRecord> templates)
    : manifest_(std::move(manifest)), templates_(std::move(templates)) {
  BuildIndex();
  for (Range& range : index_) {
    if (range.layer_index < 0 || range.end - range.begin < kViewTreeTemplates) continue;
    range.clusters = ClusterViews(
        std::span(templates_).subspan(range.begin, range.end - range.begin), kViewClusterRadiusDeg);
  }
}

TemplateArchive::TemplateArchive(ArchiveManifest manifest, std::vector<TemplateRecord> templates,
                                 std::span<const std::uint32_t> view_leaders,
                                 double view_cluster_radius_deg)
    : manifest_(std::move(manifest)), templates_(std::move(templates)) {
  BuildIndex();
  if (view_leaders.size() != templates_.size()) {
    throw FormatError("view tree: " + std::to_string(view_leaders.size()) + " entries for " +
                      std::to_string(templates_.size()) + " templates");
  }
  for (Range& range : index_) {
    if (range.layer_index < 0) continue;
    const std::size_t size = range.end - range.begin;
    std::vector<std::uint32_t> leaders(
        view_leaders.begin() + static_cast<std::ptrdiff_t>(range.begin),
        view_leaders.begin() + static_cast<std::ptrdiff_t>(range.end));
    for (std::size_t i = 0; i < size; ++i) {
      if (leaders[i] == kNoViewCluster) continue;
      if (leaders[i] < range.begin || leaders[i] >= range.end) {
        throw FormatError("view tree: template " + std::to_string(range.begin + i) +
                          " is led by template " + std::to_string(leaders[i]) +
                          ", which is not of its object and layer");
      }
      leaders[i] -= static_cast<std::uint32_t>(range.begin);
    }
    range.clusters = ClustersFromLeaders(std::span(templates_).subspan(range.begin, size), leaders,
                                         view_cluster_radius_deg);
  }
}

void TemplateArchive::BuildIndex() {
  CheckIdsAndObjects(manifest_, templates_);
  index_.clear();
  // Runs of equal (object, layer) in table order; each must occur once, and the runs of one
  // object must follow each other.
  std::set<std::pair<std::int32_t, int>> seen_layers;
  std::set<std::int32_t> closed_objects;
  std::size_t begin = 0;
  std::size_t object_begin = 0;
  for (std::size_t i = 1; i <= templates_.size(); ++i) {
    const TemplateRecord& first = templates_[begin];
    const bool at_end = i == templates_.size();
    if (!at_end && templates_[i].obj_id == first.obj_id &&
        templates_[i].layer_index == first.layer_index) {
      continue;
    }
    if (!seen_layers.insert({first.obj_id, first.layer_index}).second) {
      throw FormatError("templates of " + RunName(first.obj_id, first.layer_index) +
                        " are not contiguous");
    }
    index_.push_back({first.obj_id, first.layer_index, begin, i, {}});
    if (at_end || templates_[i].obj_id != first.obj_id) {
      if (!closed_objects.insert(first.obj_id).second) {
        throw FormatError("templates of object " + std::to_string(first.obj_id) +
                          " are not contiguous");
      }
      index_.push_back({first.obj_id, -1, object_begin, i, {}});
      object_begin = i;
    }
    begin = i;
  }
  std::sort(index_.begin(), index_.end(), [](const Range& a, const Range& b) {
    return std::tie(a.obj_id, a.layer_index) < std::tie(b.obj_id, b.layer_index);
  });
}

const ArchiveObject& TemplateArchive::Object(std::int32_t obj_id) const {
  for (const ArchiveObject& object : manifest_.objects) {
    if (object.obj_id == obj_id) return object;
  }
  throw Error("the archive has no object " + std::to_string(obj_id));
}

std::span<const TemplateRecord> TemplateArchive::TemplatesOf(std::int32_t obj_id) const {
  return TemplatesOf(obj_id, -1);
}

const TemplateArchive::Range* TemplateArchive::FindRange(std::int32_t obj_id,
                                                         int layer_index) const {
  const auto it = std::lower_bound(index_.begin(), index_.end(), std::pair(obj_id, layer_index),
                                   [](const Range& range, const std::pair<std::int32_t, int>& key) {
                                     return std::pair(range.obj_id, range.layer_index) < key;
                                   });
  if (it == index_.end() || it->obj_id != obj_id || it->layer_index != layer_index) return nullptr;
  return &*it;
}

std::span<const TemplateRecord> TemplateArchive::TemplatesOf(std::int32_t obj_id,
                                                             int layer_index) const {
  const Range* range = FindRange(obj_id, layer_index);
  if (range == nullptr) return {};
  return std::span<const TemplateRecord>(templates_)
      .subspan(range->begin, range->end - range->begin);
}

std::span<const ViewCluster> TemplateArchive::ViewClustersOf(std::int32_t obj_id,
                                                             int layer_index) const {
  const Range* range = layer_index < 0 ? nullptr : FindRange(obj_id, layer_index);
  if (range == nullptr) return {};
  return range->clusters;
}

std::size_t TemplateArchive::ViewClusterCount() const {
  std::size_t count = 0;
  for (const Range& range : index_) count += range.clusters.size();
  return count;
}

std::vector<std::uint32_t> TemplateArchive::ViewLeaders() const {
  std::vector<std::uint32_t> leaders(templates_.size(), kNoViewCluster);
  for (const Range& range : index_) {
    const std::vector<std::uint32_t> layer =
        ClusterLeaders(range.clusters, range.end - range.begin);
    for (std::size_t i = 0; i < layer.size(); ++i) {
      if (layer[i] != kNoViewCluster) {
        leaders[range.begin + i] = layer[i] + static_cast<std::uint32_t>(range.begin);
      }
    }
  }
  return leaders;
}

}  // namespace layermod
