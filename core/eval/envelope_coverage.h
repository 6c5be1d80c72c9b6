// SPDX-License-Identifier: MIT
// Whether an archive's view envelope covers a pose: a miss that no template matches closely is a
// training question (widen the envelope, set the up axis), not a detection failure. A part off
// the image centre seen from above looks rolled by more than the camera is (docs/NOTES.md,
// "Full-roll tabletop archives"), so tabletop scenes hold such targets too.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dataset/bop.h"
#include "geometry/pose.h"
#include "templates/archive.h"

namespace layermod {

struct EnvelopeCheck {
  bool inside = true;
  double view_gap_deg = 0.0;  // from the pose's view direction to the nearest template view
  double roll_deg = 0.0;      // the pose's in-plane rotation, as the templates' roll measures it
  // The direction the camera sees the part from, in the profile's upright frame (as ViewAngles).
  double azimuth_deg = 0.0;
  double elevation_deg = 0.0;
  double depth_mm = 0.0;  // camera to sphere centre along the optical axis
  std::string reason;     // why it is outside; empty inside
};

// One object's envelope as its templates sample it: view directions (in the upright frame of
// its training profile), the roll range and the depth layers. A pose is outside when it is more
// than one sampling step beyond all of them: its view direction farther than the typical
// spacing of neighbouring template views from every one, its roll outside the trained rolls by
// more than a roll step, or its depth beyond the first/last layer by more than a layer spacing.
class ViewEnvelope {
 public:
  // Throws Error when the archive has no templates of `obj_id`.
  ViewEnvelope(const TemplateArchive& archive, std::int32_t obj_id);

  EnvelopeCheck Check(const Pose& cam_from_model) const;

  double view_step_deg() const { return view_step_deg_; }

 private:
  Eigen::Matrix3d upright_from_model_;
  Eigen::Vector3d centre_in_model_;
  std::vector<Eigen::Vector3d> directions_;  // distinct template view directions
  double view_step_deg_ = 0.0;               // median angle to the nearest other direction
  double roll_min_deg_ = 0.0;
  double roll_max_deg_ = 0.0;
  double roll_step_deg_ = 0.0;
  bool full_roll_ = false;
  double depth_min_mm_ = 0.0;  // first and last layer
  double depth_max_mm_ = 0.0;
  double layer_spacing_mm_ = 0.0;
};

// A frame's ground-truth instance against an archive's envelope.
struct GroundTruthCoverage {
  std::int32_t obj_id = 0;
  std::optional<EnvelopeCheck> check;  // empty: the archive has no templates of that object
};

// The envelopes of every object of one or more archives, by object id. Building one costs a pass
// over the object's template views (their spacing), so they are built once per archive and then
// check any number of poses.
class ObjectEnvelopes {
 public:
  ObjectEnvelopes() = default;
  explicit ObjectEnvelopes(const TemplateArchive& archive) { Add(archive); }

  void Add(const TemplateArchive& archive);  // each of its objects
  // Throws std::out_of_range when no archive added has templates of `obj_id`.
  const ViewEnvelope& At(std::int32_t obj_id) const { return by_object_.at(obj_id); }
  // One entry per instance of `ground_truth`, in its order.
  std::vector<GroundTruthCoverage> Check(const std::vector<BopGroundTruth>& ground_truth) const;

 private:
  std::map<std::int32_t, ViewEnvelope> by_object_;
};

}  // namespace layermod
