// SPDX-License-Identifier: MIT
// How a part lies when it is put down on a table: on a flat face of its convex hull that holds
// its centre of mass. These are the likely up axes of a mesh (up_axis.h), offered to a user who
// does not know which axis of the mesh points up.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace layermod {

// A stable pose: the part lies on a hull face and its centre of mass is above that face.
struct RestingPose {
  Eigen::Vector3d up_in_model = Eigen::Vector3d::UnitZ();  // unit; minus the face's outward normal
  // How often a part dropped in a random orientation comes to rest this way up: the solid angle,
  // seen from the centre of mass, of this face and of the unstable faces from which a part tips
  // onto it (quasi-static draining; Goldberg et al., "Part pose statistics", 1999), over the whole
  // sphere. Stable faces within kAxisNameToleranceDeg of each other are one pose: their shares
  // add up, and the direction, margin and height are the likeliest face's.
  double probability = 0.0;
  double stability_margin_mm = 0.0;  // centre of mass, projected on the face, to its nearest edge
  double height_mm = 0.0;            // of the centre of mass above the face
  std::optional<std::string> axis_name;  // "+x" .. "-z" within kAxisNameToleranceDeg
};

struct RestingPoses {
  // The stable faces, most likely first, none twice along one axis; empty when the mesh spans no
  // volume. Their probabilities sum to 1: a part that lands on an unstable face tips onto a
  // stable one.
  std::vector<RestingPose> poses;
  Eigen::Vector3d centre_of_mass = Eigen::Vector3d::Zero();  // model frame
  // True: the centre of the solid the mesh encloses (uniform density). False: the mesh is open
  // or inside out, and the centre of its convex hull's volume stands in for it.
  bool from_closed_mesh = false;
};

// A pose is named after a model axis when its up direction is this close to it: CAD parts rest
// on faces normal to an axis, scanned ones on bases a few degrees off.
inline constexpr double kAxisNameToleranceDeg = 5.0;
// The up axis chosen for training is questioned (train warns) unless it is within
// kRestingUpToleranceDeg of a stable pose the part takes at least kLikelyRestProbability of the
// time. 10 degrees: a scanned base is uneven and the view envelope (elevation, roll) is far
// coarser than that. 5 %: faces rarer than that are chamfers and bevels nobody calls "up".
inline constexpr double kRestingUpToleranceDeg = 10.0;
inline constexpr double kLikelyRestProbability = 0.05;

// The centre of mass of the solid a closed, outward-oriented triangle mesh encloses (signed
// tetrahedron volumes, uniform density); nullopt when the mesh has a border, is not consistently
// oriented, or encloses no positive volume.
std::optional<Eigen::Vector3d> SolidCentreOfMass(const std::vector<Eigen::Vector3d>& vertices,
                                                 const std::vector<std::array<int, 3>>& triangles);

// The stable resting poses of the solid bounded by the mesh. Throws Error on non-finite vertices.
RestingPoses FindRestingPoses(const std::vector<Eigen::Vector3d>& vertices,
                              const std::vector<std::array<int, 3>>& triangles);

// The poses with probability >= kLikelyRestProbability, most likely first.
std::vector<RestingPose> LikelyRestingPoses(const RestingPoses& rest);

// The most likely stable pose whose up direction is within kRestingUpToleranceDeg of that of
// `upright_from_model` (UpDirectionInModel); nullopt when the part never rests that way up.
std::optional<RestingPose> RestingPoseAlong(const RestingPoses& rest,
                                            const Eigen::Matrix3d& upright_from_model);

// Whether RestingPoseAlong finds a pose with probability >= kLikelyRestProbability.
bool IsLikelyRestingUp(const RestingPoses& rest, const Eigen::Matrix3d& upright_from_model);

// "+z" for a pose along a model axis, "tilted (0.12, -0.70, 0.70)" (up_in_model) otherwise.
std::string RestingPoseName(const RestingPose& pose);

}  // namespace layermod
