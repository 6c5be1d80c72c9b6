// SPDX-License-Identifier: MIT
#pragma once

// Where things stand in a synthetic scene: objects upright on a table (world z = 0, +Z up), the
// camera on the table's upper hemisphere looking at the target, the light from above.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <vector>

#include "geometry/camera.h"
#include "geometry/pose.h"
#include "geometry/sphere.h"
#include "mesh/render_mesh.h"
#include "synth/model_library.h"
#include "synth/synth_options.h"

namespace layermod {

// One thing standing on the table.
struct PlacedItem {
  std::int32_t obj_id = 0;           // model id; 0 for a primitive (not annotated)
  const RenderMesh* mesh = nullptr;  // owned by the model library or SceneLayout::primitives
  Pose world_from_item;
  Eigen::Vector2d footprint_centre = Eigen::Vector2d::Zero();  // world xy (mm)
  double footprint_radius_mm = 0.0;  // every vertex is within this xy distance of the centre
  Sphere bound;                      // a bounding sphere in world coordinates
};

struct CameraSample {
  Pose cam_from_world;
  Eigen::Vector3d centre_in_world = Eigen::Vector3d::Zero();
  double azimuth_deg = 0.0;    // of the camera around the target, on the table
  double elevation_deg = 0.0;  // above the table
  double roll_deg = 0.0;       // in-plane rotation
  double distance_mm = 0.0;    // camera centre to the target's sphere centre
};

struct SceneLayout {
  CameraSample camera;
  std::vector<PlacedItem> items;      // items[0] is the target
  std::deque<RenderMesh> primitives;  // meshes of the primitive items (stable addresses)
  Eigen::AlignedBox2d table_extent;   // the table top (world xy, mm); clutter stays on it
  Eigen::Vector3d light_to_world = Eigen::Vector3d::UnitZ();  // unit, towards the light
  double ambient = 0.4;
};

// Stands `mesh` on the table: turned upright by `upright_from_model` (its up axis to +Z, see
// geometry/up_axis.h), tilted by `tilt_rad` about the horizontal `tilt_axis`, rotated by `yaw_rad`
// about +Z, resting on its lowest vertex, and shifted so that its sphere centre is above `xy`
// (world mm).
PlacedItem PlaceUpright(const RenderMesh& mesh, const Sphere& sphere, std::int32_t obj_id,
                        double yaw_rad, const Eigen::Vector3d& tilt_axis, double tilt_rad,
                        const Eigen::Vector2d& xy,
                        const Eigen::Matrix3d& upright_from_model = Eigen::Matrix3d::Identity());

// A random upright pose of `mesh` at `xy` (yaw uniform, tilt up to options.max_tilt_deg, the
// models' up axis options.upright_from_model), or with options.any_orientation a rotation
// uniform over all (the part resting on its lowest vertex, as in a bin).
PlacedItem PlaceRandomUpright(const RenderMesh& mesh, const Sphere& sphere, std::int32_t obj_id,
                              const Eigen::Vector2d& xy, const SynthOptions& options,
                              std::mt19937_64& rng);

// The camera looking from (azimuth, elevation, distance) at `target`'s sphere centre, rolled
// about its optical axis, then turned so that the sphere centre is seen at `pixel`.
Pose LookAtFrom(const Eigen::Vector3d& target_centre, const Eigen::Vector3d& camera_centre,
                double roll_rad, const PinholeCamera& camera, const Eigen::Vector2d& pixel);

// True when every vertex of `mesh` at `cam_from_mesh` is in front of the camera and projects at
// least margin_px inside the image.
bool InsideImage(const RenderMesh& mesh, const Pose& cam_from_mesh, const PinholeCamera& camera,
                 int margin_px);

// A camera of the evaluation envelope seeing the whole target; nullopt when none was found in
// a bounded number of tries (the target is too large for the image at these distances).
std::optional<CameraSample> SampleCamera(const PlacedItem& target, const PinholeCamera& camera,
                                         const SynthOptions& options, std::mt19937_64& rng);

// Adds 1..clutter other models (from `models`, never the target's id) and 1..clutter primitives
// around the target on the table, some between the camera and the target, none overlapping
// another's footprint or too close to the camera. Replaces any clutter already in the layout.
void PlaceClutter(SceneLayout& layout, const std::map<std::int32_t, SynthModel>& models,
                  const SynthOptions& options, std::mt19937_64& rng);

// Adds a primitive floating in the line of sight between the camera and the target (a bar, a
// gripper, a bin's rim), shifted sideways so that about `cover` (0..1) of the target's width is
// hidden. For cameras so high that nothing standing on the table hides the target.
void PlaceSightOccluder(SceneLayout& layout, double cover, std::mt19937_64& rng);

// A table top around the target's footprint, its edges 0.45..1.2 m from the target's centre.
void SampleTable(SceneLayout& layout, std::mt19937_64& rng);

// A light from above (within 35 degrees of vertical) and an ambient term in [0.3, 0.5].
void SampleLight(SceneLayout& layout, std::mt19937_64& rng);

}  // namespace layermod
