// SPDX-License-Identifier: MIT
#include "synth/scene_layout.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "synth/primitives.h"
#include "synth/random_draws.h"

namespace layermod {
namespace {

constexpr int kCameraTries = 40;     // (distance, direction) samples
constexpr int kPixelTries = 30;      // aim points per camera sample
constexpr int kPlacementTries = 25;  // positions per clutter item
constexpr double kFootprintGapMm = 5.0;
constexpr double kCameraClearanceMm = 60.0;
constexpr double kOccluderProbability = 0.5;

Eigen::Vector3d DirectionFrom(double azimuth_rad, double elevation_rad) {
  return {std::cos(elevation_rad) * std::cos(azimuth_rad),
          std::cos(elevation_rad) * std::sin(azimuth_rad), std::sin(elevation_rad)};
}

// Rotated (not yet translated) vertices' lowest z and largest xy distance from the rotated
// sphere centre.
void RotatedExtent(const RenderMesh& mesh, const Eigen::Matrix3d& rotation,
                   const Eigen::Vector3d& centre, double& min_z, double& radius_xy) {
  min_z = std::numeric_limits<double>::max();
  double radius2 = 0.0;
  for (const Eigen::Vector3f& p : mesh.positions) {
    const Eigen::Vector3d q = rotation * p.cast<double>();
    min_z = std::min(min_z, q.z());
    radius2 = std::max(radius2, (q - centre).head<2>().squaredNorm());
  }
  radius_xy = std::sqrt(radius2);
}

// A box or a cylinder of random size and colour (grey or a muted colour); occluders are tall
// enough to hide a part of the target from cameras well above the table.
RenderMesh RandomPrimitive(bool occluder, std::mt19937_64& rng) {
  const double min_height = occluder ? 80.0 : 25.0;
  Eigen::Vector3f color;
  if (Uniform(rng, 0.0, 1.0) < 0.5) {
    color.setConstant(static_cast<float>(Uniform(rng, 0.25, 0.9)));
  } else {
    const double hue = Uniform(rng, 0.0, 6.0);
    const double saturation = Uniform(rng, 0.25, 0.75);
    const double value = Uniform(rng, 0.35, 0.9);
    for (int c = 0; c < 3; ++c) {
      // HSV to RGB: each channel's distance from its hue sector.
      const double k = std::fmod(5.0 - 2.0 * c + hue, 6.0);
      const double weight = std::clamp(std::min(k, 4.0 - k), 0.0, 1.0);
      color[c] = static_cast<float>(value * (1.0 - saturation * weight));
    }
  }
  if (Uniform(rng, 0.0, 1.0) < 0.6) {
    // One draw per statement (synth/random_draws.h).
    const auto height = static_cast<float>(Uniform(rng, min_height, 200.0));
    const auto depth = static_cast<float>(Uniform(rng, 30.0, 140.0));
    const auto width = static_cast<float>(Uniform(rng, 30.0, 140.0));
    return MakeBoxMesh(Eigen::Vector3f(width, depth, height), color);
  }
  const auto height = static_cast<float>(Uniform(rng, std::max(40.0, min_height), 200.0));
  const auto radius = static_cast<float>(Uniform(rng, 15.0, 60.0));
  return MakeCylinderMesh(radius, height, 32, color);
}

Sphere PrimitiveSphere(const RenderMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3f& p : mesh.positions) points.push_back(p.cast<double>());
  return MinimalEnclosingSphere(points);
}

bool Overlaps(const PlacedItem& item, const std::vector<PlacedItem>& placed) {
  return std::any_of(placed.begin(), placed.end(), [&item](const PlacedItem& other) {
    const double distance = (item.footprint_centre - other.footprint_centre).norm();
    return distance < item.footprint_radius_mm + other.footprint_radius_mm + kFootprintGapMm;
  });
}

bool OnTable(const PlacedItem& item, const Eigen::AlignedBox2d& table) {
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(item.footprint_radius_mm);
  return table.contains(item.footprint_centre - reach) &&
         table.contains(item.footprint_centre + reach);
}

// Where an item's footprint centre goes: an occluder stands between the camera and the target,
// shifted sideways so that it hides a part of the target, not all of it; other items anywhere
// around the target (occluders too when the camera is so high that none fits in front).
Eigen::Vector2d ClutterPosition(const SceneLayout& layout, double item_radius, bool occluder,
                                std::mt19937_64& rng) {
  const PlacedItem& target = layout.items.front();
  const double touching = target.footprint_radius_mm + item_radius + kFootprintGapMm;
  if (!occluder) {
    const double azimuth = Uniform(rng, -kPi, kPi);
    return target.footprint_centre + (touching + Uniform(rng, 0.0, 250.0)) *
                                         Eigen::Vector2d(std::cos(azimuth), std::sin(azimuth));
  }
  const Eigen::Vector2d to_camera =
      layout.camera.centre_in_world.head<2>() - target.footprint_centre;
  const double camera_range = to_camera.norm();
  const double farthest = 0.6 * camera_range;
  if (farthest <= touching) return ClutterPosition(layout, item_radius, false, rng);
  const Eigen::Vector2d along = to_camera / camera_range;
  const Eigen::Vector2d across(-along.y(), along.x());
  const double side = Uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
  const double offset = side * Uniform(rng, 0.2, 0.9);
  const double distance_mm = Uniform(rng, touching, std::min(farthest, touching + 80.0));
  return target.footprint_centre + distance_mm * along +
         offset * (target.footprint_radius_mm + item_radius) * across;
}

// Tries positions around the target for a mesh; the item, or nullopt when every try collided.
std::optional<PlacedItem> PlaceNear(const SceneLayout& layout, const RenderMesh& mesh,
                                    const Sphere& sphere, std::int32_t obj_id, bool occluder,
                                    const SynthOptions& options, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < kPlacementTries; ++attempt) {
    PlacedItem item =
        PlaceRandomUpright(mesh, sphere, obj_id, Eigen::Vector2d::Zero(), options, rng);
    const Eigen::Vector2d shift = ClutterPosition(layout, item.footprint_radius_mm, occluder, rng);
    item.world_from_item.t.head<2>() += shift;
    item.footprint_centre += shift;
    item.bound.centre.head<2>() += shift;
    const double clearance = (item.bound.centre - layout.camera.centre_in_world).norm();
    if (clearance < item.bound.radius_mm + kCameraClearanceMm) continue;
    if (Overlaps(item, layout.items) || !OnTable(item, layout.table_extent)) continue;
    return item;
  }
  return std::nullopt;
}

}  // namespace

PlacedItem PlaceUpright(const RenderMesh& mesh, const Sphere& sphere, std::int32_t obj_id,
                        double yaw_rad, const Eigen::Vector3d& tilt_axis, double tilt_rad,
                        const Eigen::Vector2d& xy, const Eigen::Matrix3d& upright_from_model) {
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(tilt_rad, tilt_axis.normalized()))
                                       .toRotationMatrix() *
                                   upright_from_model;
  const Eigen::Vector3d centre = rotation * sphere.centre;
  double min_z = 0.0;
  double radius_xy = 0.0;
  RotatedExtent(mesh, rotation, centre, min_z, radius_xy);
  PlacedItem item;
  item.obj_id = obj_id;
  item.mesh = &mesh;
  item.world_from_item.R = rotation;
  item.world_from_item.t = Eigen::Vector3d(xy.x() - centre.x(), xy.y() - centre.y(), -min_z);
  item.footprint_centre = xy;
  item.footprint_radius_mm = radius_xy;
  item.bound.centre = item.world_from_item * sphere.centre;
  item.bound.radius_mm = sphere.radius_mm;
  return item;
}

PlacedItem PlaceRandomUpright(const RenderMesh& mesh, const Sphere& sphere, std::int32_t obj_id,
                              const Eigen::Vector2d& xy, const SynthOptions& options,
                              std::mt19937_64& rng) {
  const double yaw = Uniform(rng, -kPi, kPi);
  const double tilt_azimuth = Uniform(rng, -kPi, kPi);
  const double tilt = DegToRad(Uniform(rng, 0.0, options.max_tilt_deg));
  const Eigen::Vector3d axis(std::cos(tilt_azimuth), std::sin(tilt_azimuth), 0.0);
  const Eigen::Matrix3d upright_from_model =
      options.any_orientation ? UniformRotation(rng) : options.upright_from_model;
  return PlaceUpright(mesh, sphere, obj_id, yaw, axis, tilt, xy, upright_from_model);
}

Pose LookAtFrom(const Eigen::Vector3d& target_centre, const Eigen::Vector3d& camera_centre,
                double roll_rad, const PinholeCamera& camera, const Eigen::Vector2d& pixel) {
  // Rows of cam_from_world: right, down, forward (image x, image y, optical axis).
  const Eigen::Vector3d forward = (target_centre - camera_centre).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d look;
  look.row(0) = right;
  look.row(1) = down;
  look.row(2) = forward;
  const Eigen::Matrix3d roll =
      Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  // Turn the optical axis away from the target so that the target is seen at `pixel`.
  const Eigen::Vector3d ray((pixel.x() - camera.cx) / camera.fx,
                            (pixel.y() - camera.cy) / camera.fy, 1.0);
  const Eigen::Matrix3d aim =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), ray.normalized())
          .toRotationMatrix();
  Pose cam_from_world;
  cam_from_world.R = aim * roll * look;
  cam_from_world.t = -(cam_from_world.R * camera_centre);
  return cam_from_world;
}

bool InsideImage(const RenderMesh& mesh, const Pose& cam_from_mesh, const PinholeCamera& camera,
                 int margin_px) {
  const double low_x = margin_px;
  const double low_y = margin_px;
  const double high_x = camera.width - 1 - margin_px;
  const double high_y = camera.height - 1 - margin_px;
  for (const Eigen::Vector3f& p : mesh.positions) {
    const Eigen::Vector3d q = cam_from_mesh * p.cast<double>();
    if (q.z() <= 1.0) return false;
    const Eigen::Vector2d pixel = camera.Project(q);
    if (pixel.x() < low_x || pixel.x() > high_x || pixel.y() < low_y || pixel.y() > high_y) {
      return false;
    }
  }
  return true;
}

std::optional<CameraSample> SampleCamera(const PlacedItem& target, const PinholeCamera& camera,
                                         const SynthOptions& options, std::mt19937_64& rng) {
  const double margin = options.margin_px;
  for (int attempt = 0; attempt < kCameraTries; ++attempt) {
    CameraSample sample;
    sample.azimuth_deg = Uniform(rng, 0.0, 360.0);
    sample.elevation_deg = Uniform(rng, options.elevation_min_deg, options.elevation_max_deg);
    sample.roll_deg = Uniform(rng, -options.roll_max_deg, options.roll_max_deg);
    sample.distance_mm = Uniform(rng, options.dmin_mm, options.dmax_mm);
    sample.centre_in_world =
        target.bound.centre + sample.distance_mm * DirectionFrom(DegToRad(sample.azimuth_deg),
                                                                 DegToRad(sample.elevation_deg));
    for (int aim = 0; aim < kPixelTries; ++aim) {
      // The last try aims at the principal point, where an object that fits at all fits best.
      Eigen::Vector2d pixel(camera.cx, camera.cy);
      if (aim + 1 < kPixelTries) {
        pixel.y() = Uniform(rng, margin, camera.height - 1 - margin);  // y first: random_draws.h
        pixel.x() = Uniform(rng, margin, camera.width - 1 - margin);
      }
      sample.cam_from_world = LookAtFrom(target.bound.centre, sample.centre_in_world,
                                         DegToRad(sample.roll_deg), camera, pixel);
      if (InsideImage(*target.mesh, sample.cam_from_world * target.world_from_item, camera,
                      options.margin_px)) {
        return sample;
      }
    }
  }
  return std::nullopt;
}

void PlaceClutter(SceneLayout& layout, const std::map<std::int32_t, SynthModel>& models,
                  const SynthOptions& options, std::mt19937_64& rng) {
  layout.items.resize(1);
  layout.primitives.clear();
  if (options.clutter == 0) return;
  std::vector<const SynthModel*> others;
  for (const auto& [obj_id, model] : models) {
    if (obj_id != layout.items.front().obj_id) others.push_back(&model);
  }
  std::shuffle(others.begin(), others.end(), rng);
  const SynthModel* target = nullptr;
  for (const auto& [obj_id, model] : models) {
    if (obj_id == layout.items.front().obj_id) target = &model;
  }
  for (int copy = 1; copy < options.instances && target != nullptr; ++copy) {
    if (auto item =
            PlaceNear(layout, target->mesh, target->sphere, target->obj_id, false, options, rng)) {
      layout.items.push_back(*item);
    }
  }
  const int model_count =
      std::min<int>(UniformInt(rng, 1, options.clutter), static_cast<int>(others.size()));
  const int primitive_count = UniformInt(rng, 1, options.clutter);
  const int total = model_count + primitive_count;
  const int first_occluder = UniformInt(rng, 0, total - 1);  // at least one tries to occlude
  for (int i = 0; i < total; ++i) {
    const bool occluder = i == first_occluder || Uniform(rng, 0.0, 1.0) < kOccluderProbability;
    std::optional<PlacedItem> item;
    if (i < model_count) {
      const SynthModel& model = *others[static_cast<std::size_t>(i)];
      item = PlaceNear(layout, model.mesh, model.sphere, model.obj_id, occluder, options, rng);
    } else {
      layout.primitives.push_back(RandomPrimitive(occluder, rng));
      const RenderMesh& mesh = layout.primitives.back();
      item = PlaceNear(layout, mesh, PrimitiveSphere(mesh), 0, occluder, options, rng);
    }
    if (item) layout.items.push_back(*item);
  }
}

void PlaceSightOccluder(SceneLayout& layout, double cover, std::mt19937_64& rng) {
  const PlacedItem& target = layout.items.front();
  const Eigen::Vector3d to_camera = layout.camera.centre_in_world - target.bound.centre;
  const double along = Uniform(rng, 0.3, 0.6);  // of the way from the target to the camera
  // Sideways in the view, so that the occluder's edge crosses the target: at `cover` = 0 it
  // just touches the target's outline, at 1 it is centred on it.
  const Eigen::Vector3d forward = -to_camera.normalized();
  Eigen::Vector3d side = forward.cross(Eigen::Vector3d::UnitZ());
  if (side.norm() < 1e-6) side = Eigen::Vector3d::UnitX();
  side.normalize();
  const Eigen::Vector3d up = side.cross(forward);
  const double angle = Uniform(rng, -kPi, kPi);
  const Eigen::Vector3d direction = std::cos(angle) * side + std::sin(angle) * up;
  const double scale = 1.0 - along;  // the occluder's size in the target's image terms
  const double half_width = target.bound.radius_mm * scale * Uniform(rng, 0.6, 1.2);
  const double offset = (1.0 - cover) * (target.bound.radius_mm + half_width) * scale;
  layout.primitives.push_back(RandomPrimitive(false, rng));
  RenderMesh& mesh = layout.primitives.back();
  const Sphere sphere = PrimitiveSphere(mesh);
  const double shrink = half_width / std::max(sphere.radius_mm, 1.0);
  for (Eigen::Vector3f& p : mesh.positions) {
    p = ((p.cast<double>() - sphere.centre) * shrink).cast<float>();
  }
  PlacedItem item;
  item.mesh = &mesh;
  item.world_from_item.R = Eigen::AngleAxisd(Uniform(rng, -kPi, kPi), direction).toRotationMatrix();
  item.world_from_item.t = target.bound.centre + along * to_camera + offset * direction;
  item.footprint_centre = item.world_from_item.t.head<2>();
  item.bound.centre = item.world_from_item.t;
  item.bound.radius_mm = half_width;
  layout.items.push_back(item);
}

void SampleTable(SceneLayout& layout, std::mt19937_64& rng) {
  const Eigen::Vector2d centre = layout.items.front().footprint_centre;
  const Eigen::Vector2d low = UniformVector2(rng, 450.0, 1200.0);
  const Eigen::Vector2d high = UniformVector2(rng, 450.0, 1200.0);
  layout.table_extent = Eigen::AlignedBox2d(centre - low, centre + high);
}

void SampleLight(SceneLayout& layout, std::mt19937_64& rng) {
  const double tilt = DegToRad(Uniform(rng, 0.0, 35.0));
  const double azimuth = Uniform(rng, -kPi, kPi);
  layout.light_to_world = DirectionFrom(azimuth, kPi / 2 - tilt);
  layout.ambient = Uniform(rng, 0.3, 0.5);
}

}  // namespace layermod
