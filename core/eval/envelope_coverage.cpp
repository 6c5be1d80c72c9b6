// SPDX-License-Identifier: MIT
#include "eval/envelope_coverage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/views.h"
#include "util/error.h"

namespace layermod {
namespace {

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return RadToDeg(std::atan2(a.cross(b).norm(), a.dot(b)));
}

std::vector<Eigen::Vector3d> DistinctDirections(const TemplateArchive& archive,
                                                std::int32_t obj_id) {
  std::vector<Eigen::Vector3d> directions;
  for (const TemplateRecord& tmpl : archive.TemplatesOf(obj_id, 0)) {
    const Eigen::Vector3d d = DirectionFromAngles(tmpl.view.azimuth_deg, tmpl.view.elevation_deg);
    const bool seen =
        std::any_of(directions.begin(), directions.end(),
                    [&](const Eigen::Vector3d& other) { return AngleDeg(d, other) < 1e-6; });
    if (!seen) directions.push_back(d);
  }
  return directions;
}

double MedianNearestNeighbourDeg(const std::vector<Eigen::Vector3d>& directions) {
  if (directions.size() < 2) return 180.0;
  std::vector<double> nearest;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    double best = 180.0;
    for (std::size_t j = 0; j < directions.size(); ++j) {
      if (j != i) best = std::min(best, AngleDeg(directions[i], directions[j]));
    }
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

// The smallest rotation that turns `from` onto `to` (both unit).
Eigen::Matrix3d AlignRotation(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
}

double WrapDeg(double angle_deg) {
  while (angle_deg > 180.0) angle_deg -= 360.0;
  while (angle_deg <= -180.0) angle_deg += 360.0;
  return angle_deg;
}

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b, c);
  return text;
}

}  // namespace

ViewEnvelope::ViewEnvelope(const TemplateArchive& archive, std::int32_t obj_id) {
  const ArchiveObject& object = archive.Object(obj_id);
  const ViewSamplingOptions& views = object.profile.views;
  upright_from_model_ = views.upright_from_model;
  centre_in_model_ = object.sphere.centre;
  directions_ = DistinctDirections(archive, obj_id);
  if (directions_.empty() || object.layer_depths_mm.empty()) {
    throw Error("envelope: the archive has no templates of object " + std::to_string(obj_id));
  }
  view_step_deg_ = MedianNearestNeighbourDeg(directions_);
  roll_min_deg_ = views.roll.min_deg;
  roll_max_deg_ = views.roll.Values().back();
  roll_step_deg_ = views.roll.Count() > 1 ? views.roll.step_deg : 0.0;
  full_roll_ = roll_max_deg_ - roll_min_deg_ + roll_step_deg_ >= 360.0 - 1e-6;
  depth_min_mm_ = object.layer_depths_mm.front();
  depth_max_mm_ = object.layer_depths_mm.back();
  layer_spacing_mm_ = object.layer_depths_mm.size() > 1
                          ? (depth_max_mm_ - depth_min_mm_) / (object.layer_depths_mm.size() - 1)
                          : object.sphere.radius_mm;
}

EnvelopeCheck ViewEnvelope::Check(const Pose& cam_from_model) const {
  EnvelopeCheck check;
  const Eigen::Vector3d centre_in_cam = cam_from_model * centre_in_model_;
  check.depth_mm = centre_in_cam.z();
  // The camera turned to look straight at the sphere centre, as every template's camera does:
  // an object off the image centre is seen from the same direction, at the same roll.
  const Pose aimed{
      AlignRotation(centre_in_cam.normalized(), Eigen::Vector3d::UnitZ()) * cam_from_model.R,
      Eigen::Vector3d(0.0, 0.0, centre_in_cam.norm())};
  const Eigen::Vector3d camera_in_model = -(aimed.R.transpose() * aimed.t) + centre_in_model_;
  const Eigen::Vector3d to_camera =
      (upright_from_model_ * (camera_in_model - centre_in_model_)).normalized();
  check.view_gap_deg = 180.0;
  for (const Eigen::Vector3d& direction : directions_) {
    check.view_gap_deg = std::min(check.view_gap_deg, AngleDeg(to_camera, direction));
  }
  check.elevation_deg = RadToDeg(std::asin(std::clamp(to_camera.z(), -1.0, 1.0)));
  check.azimuth_deg = RadToDeg(std::atan2(to_camera.y(), to_camera.x()));
  const Pose unrolled =
      CamFromModelForView({check.azimuth_deg, check.elevation_deg, 0.0}, centre_in_model_,
                          centre_in_cam.norm(), upright_from_model_);
  const Eigen::Matrix3d roll = aimed.R * unrolled.R.transpose();
  check.roll_deg = RadToDeg(std::atan2(roll(1, 0), roll(0, 0)));

  if (check.view_gap_deg > view_step_deg_) {
    check.reason = Format("seen from %.0f deg elevation, %.1f deg from every template view",
                          check.elevation_deg, check.view_gap_deg);
  } else if (!full_roll_ && (WrapDeg(check.roll_deg - roll_min_deg_) < -roll_step_deg_ - 1e-6 ||
                             WrapDeg(check.roll_deg - roll_max_deg_) > roll_step_deg_ + 1e-6)) {
    check.reason = Format("roll %.0f deg outside the trained %.0f..%.0f deg", check.roll_deg,
                          roll_min_deg_, roll_max_deg_);
  } else if (check.depth_mm < depth_min_mm_ - layer_spacing_mm_ ||
             check.depth_mm > depth_max_mm_ + layer_spacing_mm_) {
    check.reason = Format("depth %.0f mm outside the layers %.0f..%.0f mm", check.depth_mm,
                          depth_min_mm_, depth_max_mm_);
  }
  check.inside = check.reason.empty();
  return check;
}

void ObjectEnvelopes::Add(const TemplateArchive& archive) {
  for (const ArchiveObject& object : archive.manifest().objects) {
    by_object_.emplace(object.obj_id, ViewEnvelope(archive, object.obj_id));
  }
}

std::vector<GroundTruthCoverage> ObjectEnvelopes::Check(
    const std::vector<BopGroundTruth>& ground_truth) const {
  std::vector<GroundTruthCoverage> coverage;
  for (const BopGroundTruth& instance : ground_truth) {
    GroundTruthCoverage entry{instance.obj_id, std::nullopt};
    if (const auto found = by_object_.find(instance.obj_id); found != by_object_.end()) {
      entry.check = found->second.Check(instance.cam_from_model);
    }
    coverage.push_back(std::move(entry));
  }
  return coverage;
}

}  // namespace layermod
