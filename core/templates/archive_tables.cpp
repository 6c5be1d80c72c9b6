// SPDX-License-Identifier: MIT
#include "templates/archive_tables.h"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>

#include "templates/byte_io.h"
#include "util/error.h"

namespace layermod {
namespace {

constexpr double kRotationTolerance = 1e-3;
constexpr std::size_t kLevelSlotBytes = 24;

[[noreturn]] void Fail(std::size_t index, const std::string& problem) {
  throw FormatError("template " + std::to_string(index) + ": " + problem);
}

// ---- encoding ----

void PutLevels(ByteWriter& out, const TemplateRecord& record, std::uint64_t& feature_offset) {
  for (const TemplateLevel& level : record.levels) {
    out.Put<std::int32_t>(level.pyramid_level);
    out.Put<std::int32_t>(level.width);
    out.Put<std::int32_t>(level.height);
    out.Put<std::uint32_t>(static_cast<std::uint32_t>(level.features.size()));
    out.Put<std::uint64_t>(feature_offset);
    feature_offset += level.features.size();
  }
  out.PutZeros(kLevelSlotBytes * (kMaxStoredLevels - record.levels.size()));
}

void PutRecord(ByteWriter& out, const TemplateRecord& record, std::uint64_t& feature_offset) {
  out.Put(record.id);
  out.Put(record.obj_id);
  out.Put(record.layer_index);
  out.Put(record.status);
  out.Put<std::uint8_t>(static_cast<std::uint8_t>(record.levels.size()));
  out.Put(record.layer_depth_mm);
  out.Put(record.view.azimuth_deg);
  out.Put(record.view.elevation_deg);
  out.Put(record.view.roll_deg);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) out.Put(record.cam_from_model.R(row, col));
  }
  for (int i = 0; i < 3; ++i) out.Put(record.cam_from_model.t(i));
  out.Put<std::int32_t>(record.bbox_px.x);
  out.Put<std::int32_t>(record.bbox_px.y);
  out.Put<std::int32_t>(record.bbox_px.width);
  out.Put<std::int32_t>(record.bbox_px.height);
  out.Put(record.centre_offset_px.x);
  out.Put(record.centre_offset_px.y);
  out.Put(record.centre_minus_surface_mm);
  out.Put(record.depth_edge_count);
  PutLevels(out, record, feature_offset);
}

// ---- decoding ----

struct LevelSlot {
  std::uint32_t feature_count = 0;
  std::uint64_t feature_offset = 0;
};

void GetRecordHead(ByteReader& in, TemplateRecord& record, std::size_t index, int& level_count) {
  record.id = in.Get<std::uint32_t>();
  record.obj_id = in.Get<std::int32_t>();
  record.layer_index = in.Get<std::uint16_t>();
  const auto status = in.Get<std::uint8_t>();
  if (status > static_cast<std::uint8_t>(TemplateStatus::kTooFewFeatures)) {
    Fail(index, "unknown status " + std::to_string(status));
  }
  record.status = static_cast<TemplateStatus>(status);
  level_count = in.Get<std::uint8_t>();
  if (level_count > kMaxStoredLevels) {
    Fail(index, std::to_string(level_count) + " pyramid levels, at most " +
                    std::to_string(kMaxStoredLevels) + " allowed");
  }
  record.layer_depth_mm = in.Get<float>();
  record.view.azimuth_deg = in.Get<double>();
  record.view.elevation_deg = in.Get<double>();
  record.view.roll_deg = in.Get<double>();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) record.cam_from_model.R(row, col) = in.Get<double>();
  }
  for (int i = 0; i < 3; ++i) record.cam_from_model.t(i) = in.Get<double>();
  record.bbox_px.x = in.Get<std::int32_t>();
  record.bbox_px.y = in.Get<std::int32_t>();
  record.bbox_px.width = in.Get<std::int32_t>();
  record.bbox_px.height = in.Get<std::int32_t>();
  record.centre_offset_px.x = in.Get<float>();
  record.centre_offset_px.y = in.Get<float>();
  record.centre_minus_surface_mm = in.Get<float>();
  record.depth_edge_count = in.Get<std::int32_t>();
}

using LevelSlots = std::array<LevelSlot, kMaxStoredLevels>;

LevelSlots GetLevelSlots(ByteReader& in, TemplateRecord& record, int level_count,
                         std::size_t index) {
  LevelSlots slots{};
  record.levels.resize(static_cast<std::size_t>(level_count));
  for (std::size_t k = 0; k < record.levels.size(); ++k) {
    record.levels[k].pyramid_level = in.Get<std::int32_t>();
    record.levels[k].width = in.Get<std::int32_t>();
    record.levels[k].height = in.Get<std::int32_t>();
    slots[k].feature_count = in.Get<std::uint32_t>();
    slots[k].feature_offset = in.Get<std::uint64_t>();
  }
  if (!in.SkipZeros(kLevelSlotBytes * (kMaxStoredLevels - record.levels.size()))) {
    Fail(index, "unused pyramid level slots are not zero");
  }
  return slots;
}

// The hot loop of loading: one range check, then plain little-endian decoding.
void GetFeatures(std::string_view features_bin, const LevelSlot& slot, TemplateLevel& level) {
  const std::size_t begin = static_cast<std::size_t>(slot.feature_offset) * kFeatureRecordBytes;
  const std::size_t size = static_cast<std::size_t>(slot.feature_count) * kFeatureRecordBytes;
  if (begin > features_bin.size() || size > features_bin.size() - begin) {
    throw FormatError("features run past the end of the feature table");
  }
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(features_bin.data() + begin);
  level.features.reserve(slot.feature_count);  // not resize(): no zero-filling pass
  for (std::uint32_t i = 0; i < slot.feature_count; ++i, bytes += kFeatureRecordBytes) {
    level.features.push_back(
        {static_cast<std::int16_t>(static_cast<std::uint16_t>(bytes[0] | bytes[1] << 8)),
         static_cast<std::int16_t>(static_cast<std::uint16_t>(bytes[2] | bytes[3] << 8)), bytes[4],
         // Checked by RecordValidator before anyone uses it as an enum.
         static_cast<Modality>(bytes[5])});
  }
}

// Reads the features of every level, which must follow each other in the feature table.
void GetAllFeatures(std::string_view features_bin, const LevelSlots& slots, TemplateRecord& record,
                    std::size_t index, std::uint64_t& next_feature) {
  const std::uint64_t table_features = features_bin.size() / kFeatureRecordBytes;
  for (std::size_t k = 0; k < record.levels.size(); ++k) {
    if (slots[k].feature_offset != next_feature) {
      Fail(index, "level " + std::to_string(k) + " features start at " +
                      std::to_string(slots[k].feature_offset) + ", expected " +
                      std::to_string(next_feature));
    }
    if (slots[k].feature_count > table_features - next_feature) {
      Fail(index, "level " + std::to_string(k) + " features run past the end of the feature table");
    }
    GetFeatures(features_bin, slots[k], record.levels[k]);
    next_feature += slots[k].feature_count;
  }
}

// ---- validation ----

bool IsFinite(float value) { return std::isfinite(value); }
bool IsFinite(double value) { return std::isfinite(value); }

void CheckPose(const Pose& pose, std::size_t index) {
  if (!pose.R.allFinite() || !pose.t.allFinite()) Fail(index, "pose is not finite");
  const double error =
      (pose.R.transpose() * pose.R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (error > kRotationTolerance)
    Fail(index, "rotation is not orthonormal (error " + std::to_string(error) + ")");
  if (pose.R.determinant() < 0.0) Fail(index, "rotation is a reflection (determinant -1)");
}

void CheckScalars(const TemplateRecord& record, std::size_t index) {
  if (!IsFinite(record.layer_depth_mm) || record.layer_depth_mm <= 0.0f) {
    Fail(index, "layer depth must be a positive number");
  }
  if (!IsFinite(record.view.azimuth_deg) || !IsFinite(record.view.elevation_deg) ||
      !IsFinite(record.view.roll_deg)) {
    Fail(index, "view angles are not finite");
  }
  if (!IsFinite(record.centre_offset_px.x) || !IsFinite(record.centre_offset_px.y) ||
      !IsFinite(record.centre_minus_surface_mm)) {
    Fail(index, "centre offset is not finite");
  }
  if (record.bbox_px.width < 0 || record.bbox_px.height < 0) {
    Fail(index, "bounding box has a negative size");
  }
  if (record.depth_edge_count < 0) Fail(index, "depth edge count is negative");
  if (record.status != TemplateStatus::kOk && record.status != TemplateStatus::kTooFewFeatures) {
    Fail(index, "unknown status");
  }
}

void CheckLevel(const TemplateLevel& level, int k, std::size_t index) {
  const std::string name = "level " + std::to_string(k);
  if (level.pyramid_level != k)
    Fail(index, name + " has pyramid level " + std::to_string(level.pyramid_level));
  if (level.width < 0 || level.height < 0 || level.width > kMaxLevelSizePx ||
      level.height > kMaxLevelSizePx) {
    Fail(index, name + " box " + std::to_string(level.width) + "x" + std::to_string(level.height) +
                    " is out of range");
  }
  for (const Feature& feature : level.features) {
    // The box is the features' bounding box (cv::Rect convention: width = max - min + 1).
    if (feature.x < 0 || feature.y < 0 || feature.x >= level.width || feature.y >= level.height) {
      Fail(index, name + " feature (" + std::to_string(feature.x) + ", " +
                      std::to_string(feature.y) + ") lies outside its box");
    }
    if (feature.label > 7)
      Fail(index, name + " feature label " + std::to_string(feature.label) + " is not 0..7");
    const auto modality = static_cast<std::uint8_t>(feature.modality);
    if (modality > static_cast<std::uint8_t>(Modality::kDepthNormal)) {
      Fail(index, name + " feature has unknown modality " + std::to_string(modality));
    }
  }
}

}  // namespace

EncodedTables EncodeTables(std::span<const TemplateRecord> templates) {
  EncodedTables tables;
  std::size_t feature_count = 0;
  for (const TemplateRecord& record : templates) {
    if (record.levels.size() > static_cast<std::size_t>(kMaxStoredLevels)) {
      throw Error("template " + std::to_string(record.id) + ": more than " +
                  std::to_string(kMaxStoredLevels) + " pyramid levels cannot be stored");
    }
    for (const TemplateLevel& level : record.levels) feature_count += level.features.size();
  }
  tables.templates.reserve(templates.size() * kTemplateRecordBytes);
  tables.features.reserve(feature_count * kFeatureRecordBytes);
  ByteWriter template_out(tables.templates);
  ByteWriter feature_out(tables.features);
  std::uint64_t feature_offset = 0;
  for (const TemplateRecord& record : templates) {
    PutRecord(template_out, record, feature_offset);
    for (const TemplateLevel& level : record.levels) {
      for (const Feature& feature : level.features) {
        feature_out.Put(feature.x);
        feature_out.Put(feature.y);
        feature_out.Put(feature.label);
        feature_out.Put(feature.modality);
      }
    }
  }
  tables.template_count = templates.size();
  tables.feature_count = feature_offset;
  return tables;
}

RecordValidator::RecordValidator(const ArchiveManifest& manifest) {
  for (const ArchiveObject& object : manifest.objects) {
    layer_count_[object.obj_id] = object.layer_depths_mm.size();
  }
}

void RecordValidator::Check(const TemplateRecord& record, std::size_t index) const {
  if (record.id != index) Fail(index, "id is " + std::to_string(record.id));
  const auto object = layer_count_.find(record.obj_id);
  if (object == layer_count_.end()) {
    Fail(index, "object " + std::to_string(record.obj_id) + " is not in the manifest");
  }
  if (record.layer_index >= object->second) {
    Fail(index, "layer " + std::to_string(record.layer_index) + " but object " +
                    std::to_string(record.obj_id) + " has " + std::to_string(object->second) +
                    " layers");
  }
  CheckScalars(record, index);
  CheckPose(record.cam_from_model, index);
  if (record.levels.size() > static_cast<std::size_t>(kMaxStoredLevels)) {
    Fail(index, "more than " + std::to_string(kMaxStoredLevels) + " pyramid levels");
  }
  for (std::size_t k = 0; k < record.levels.size(); ++k) {
    CheckLevel(record.levels[k], static_cast<int>(k), index);
  }
}

std::vector<TemplateRecord> DecodeTables(std::string_view templates_bin,
                                         std::string_view features_bin,
                                         const ArchiveManifest& manifest) {
  if (templates_bin.size() % kTemplateRecordBytes != 0) {
    throw FormatError("template table size " + std::to_string(templates_bin.size()) +
                      " is not a multiple of " + std::to_string(kTemplateRecordBytes));
  }
  if (features_bin.size() % kFeatureRecordBytes != 0) {
    throw FormatError("feature table size " + std::to_string(features_bin.size()) +
                      " is not a multiple of " + std::to_string(kFeatureRecordBytes));
  }
  const RecordValidator validator(manifest);
  std::vector<TemplateRecord> templates(templates_bin.size() / kTemplateRecordBytes);
  ByteReader in(templates_bin);
  std::uint64_t next_feature = 0;
  for (std::size_t index = 0; index < templates.size(); ++index) {
    TemplateRecord& record = templates[index];
    int level_count = 0;
    GetRecordHead(in, record, index, level_count);
    const LevelSlots slots = GetLevelSlots(in, record, level_count, index);
    GetAllFeatures(features_bin, slots, record, index, next_feature);
    validator.Check(record, index);
  }
  const std::uint64_t table_features = features_bin.size() / kFeatureRecordBytes;
  if (next_feature != table_features) {
    throw FormatError("feature table holds " + std::to_string(table_features) +
                      " features but the templates use " + std::to_string(next_feature));
  }
  return templates;
}

}  // namespace layermod
