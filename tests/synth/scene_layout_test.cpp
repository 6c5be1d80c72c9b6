// SPDX-License-Identifier: MIT
#include "synth/scene_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/matchers.h"
#include "synth/primitives.h"
#include "synth_fixtures.h"

namespace layermod {
namespace {

using test::MatrixNear;

Sphere SphereOf(const RenderMesh& mesh) {
  std::vector<Eigen::Vector3d> points;
  for (const auto& p : mesh.positions) points.push_back(p.cast<double>());
  return MinimalEnclosingSphere(points);
}

double LowestZ(const PlacedItem& item) {
  double low = 1e9;
  for (const auto& p : item.mesh->positions) {
    low = std::min(low, (item.world_from_item * p.cast<double>()).z());
  }
  return low;
}

TEST(SceneLayoutTest, UprightItemsRestOnTheTableAboveTheirPlace) {
  const RenderMesh box = MakeBoxMesh({40.0f, 80.0f, 30.0f}, {1.0f, 1.0f, 1.0f});
  // A box offset from its own origin, to check that the sphere centre is what is placed.
  RenderMesh shifted = box;
  for (auto& p : shifted.positions) p += Eigen::Vector3f(100.0f, -50.0f, 20.0f);
  const Sphere sphere = SphereOf(shifted);
  const PlacedItem item = PlaceUpright(shifted, sphere, 4, 0.7, Eigen::Vector3d::UnitX(),
                                       DegToRad(10.0), {250.0, -30.0});
  EXPECT_EQ(item.obj_id, 4);
  EXPECT_NEAR(LowestZ(item), 0.0, 1e-9);
  EXPECT_THAT(item.bound.centre.head<2>().eval(), MatrixNear(Eigen::Vector2d(250.0, -30.0), 1e-9));
  EXPECT_THAT(item.footprint_centre, MatrixNear(Eigen::Vector2d(250.0, -30.0), 0.0));
  // The footprint radius bounds every vertex; the box's half diagonal is the exact value.
  EXPECT_GE(item.footprint_radius_mm, std::hypot(20.0, 40.0) - 1e-6);
  EXPECT_NEAR((item.world_from_item.R * item.world_from_item.R.transpose()).trace(), 3.0, 1e-12);
}

TEST(SceneLayoutTest, AnyOrientationTurnsItemsEveryWayAndRestsThemOnTheTable) {
  const RenderMesh box = MakeBoxMesh({40.0f, 80.0f, 30.0f}, {1.0f, 1.0f, 1.0f});
  const Sphere sphere = SphereOf(box);
  SynthOptions options;
  options.any_orientation = true;
  std::mt19937_64 rng(5);
  // Where the model's +Z points: upright placements keep it within the tilt of up; uniform
  // rotations spread it over the sphere (mean z about 0, some pointing down).
  double mean_up_z = 0.0;
  int pointing_down = 0;
  constexpr int kItems = 400;
  for (int i = 0; i < kItems; ++i) {
    const PlacedItem item = PlaceRandomUpright(box, sphere, 1, {0.0, 0.0}, options, rng);
    EXPECT_NEAR(LowestZ(item), 0.0, 1e-9);
    const double up_z = item.world_from_item.R(2, 2);
    mean_up_z += up_z / kItems;
    pointing_down += up_z < -0.5 ? 1 : 0;
  }
  EXPECT_NEAR(mean_up_z, 0.0, 0.1);
  EXPECT_GT(pointing_down, kItems / 6);  // a quarter of uniform rotations point below -0.5
  options.any_orientation = false;
  const PlacedItem upright = PlaceRandomUpright(box, sphere, 1, {0.0, 0.0}, options, rng);
  EXPECT_GT(upright.world_from_item.R(2, 2), std::cos(DegToRad(options.max_tilt_deg)) - 1e-9);
}

TEST(SceneLayoutTest, LookAtSeesTheTargetAtThePixel) {
  const PinholeCamera camera = test::SmallCamera();
  const Eigen::Vector3d target(10.0, 20.0, 50.0);
  const Eigen::Vector3d centre(600.0, -300.0, 700.0);
  const Pose cam_from_world = LookAtFrom(target, centre, DegToRad(30.0), camera, {40.0, 200.0});
  const Eigen::Vector3d in_cam = cam_from_world * target;
  EXPECT_THAT(camera.Project(in_cam), MatrixNear(Eigen::Vector2d(40.0, 200.0), 1e-9));
  EXPECT_NEAR(in_cam.norm(), (target - centre).norm(), 1e-9);
  EXPECT_THAT((cam_from_world * centre).eval(), MatrixNear(Eigen::Vector3d::Zero(), 1e-9));
  EXPECT_NEAR(cam_from_world.R.determinant(), 1.0, 1e-12);
}

TEST(SceneLayoutTest, CamerasStayInTheEnvelopeAndSeeTheWholeTarget) {
  const RenderMesh box = MakeBoxMesh({120.0f, 60.0f, 90.0f}, {1.0f, 1.0f, 1.0f});
  const Sphere sphere = SphereOf(box);
  SynthOptions options = test::SmallOptions("m", {1}, 1, "o");
  options.margin_px = 6;
  std::mt19937_64 rng(3);
  for (int i = 0; i < 20; ++i) {
    const PlacedItem target = PlaceRandomUpright(box, sphere, 1, {0.0, 0.0}, options, rng);
    const auto sample = SampleCamera(target, options.camera, options, rng);
    ASSERT_TRUE(sample.has_value());
    EXPECT_GE(sample->elevation_deg, options.elevation_min_deg);
    EXPECT_LE(sample->elevation_deg, options.elevation_max_deg);
    EXPECT_LE(std::abs(sample->roll_deg), options.roll_max_deg);
    EXPECT_NEAR((sample->centre_in_world - target.bound.centre).norm(), sample->distance_mm, 1e-9);
    EXPECT_GE(sample->distance_mm, options.dmin_mm);
    EXPECT_LE(sample->distance_mm, options.dmax_mm);
    // Above the table, at the sampled elevation.
    const Eigen::Vector3d up = sample->centre_in_world - target.bound.centre;
    EXPECT_NEAR(RadToDeg(std::asin(up.z() / up.norm())), sample->elevation_deg, 1e-9);
    EXPECT_TRUE(InsideImage(box, sample->cam_from_world * target.world_from_item, options.camera,
                            options.margin_px));
  }
}

TEST(SceneLayoutTest, TooLargeTargetsFindNoCamera) {
  const RenderMesh wall = MakeBoxMesh({3000.0f, 3000.0f, 50.0f}, {1.0f, 1.0f, 1.0f});
  const SynthOptions options = test::SmallOptions("m", {1}, 1, "o");
  std::mt19937_64 rng(3);
  const PlacedItem target = PlaceRandomUpright(wall, SphereOf(wall), 1, {0.0, 0.0}, options, rng);
  EXPECT_FALSE(SampleCamera(target, options.camera, options, rng).has_value());
}

TEST(SceneLayoutTest, ClutterStandsApartOnTheTable) {
  const RenderMesh box = MakeBoxMesh({80.0f, 60.0f, 90.0f}, {1.0f, 1.0f, 1.0f});
  std::map<std::int32_t, SynthModel> models;
  for (const std::int32_t id : {1, 2, 3}) {
    SynthModel& model = models[id];
    model.obj_id = id;
    model.mesh = box;
    model.sphere = SphereOf(box);
  }
  SynthOptions options = test::SmallOptions("m", {1}, 1, "o");
  std::mt19937_64 rng(5);
  int placed = 0;
  for (int trial = 0; trial < 10; ++trial) {
    SceneLayout layout;
    layout.items.push_back(
        PlaceRandomUpright(models.at(1).mesh, models.at(1).sphere, 1, {0.0, 0.0}, options, rng));
    layout.camera = *SampleCamera(layout.items[0], options.camera, options, rng);
    SampleTable(layout, rng);
    PlaceClutter(layout, models, options, rng);
    for (std::size_t i = 1; i < layout.items.size(); ++i) {
      const PlacedItem& item = layout.items[i];
      EXPECT_NE(item.obj_id, 1);  // never the target's model
      EXPECT_NEAR(LowestZ(item), 0.0, 1e-6);
      for (std::size_t j = 0; j < i; ++j) {
        const double gap = (item.footprint_centre - layout.items[j].footprint_centre).norm() -
                           item.footprint_radius_mm - layout.items[j].footprint_radius_mm;
        EXPECT_GT(gap, 0.0);
      }
      const Eigen::Vector2d reach = Eigen::Vector2d::Constant(item.footprint_radius_mm);
      EXPECT_TRUE(layout.table_extent.contains(item.footprint_centre + reach));
      EXPECT_TRUE(layout.table_extent.contains(item.footprint_centre - reach));
      ++placed;
    }
    EXPECT_LE(layout.items.size(), 1u + 2u + 3u);  // 2 other models, up to 3 primitives
  }
  EXPECT_GT(placed, 10);
  options.clutter = 0;
  SceneLayout bare;
  bare.items.push_back(
      PlaceRandomUpright(models.at(1).mesh, models.at(1).sphere, 1, {0.0, 0.0}, options, rng));
  PlaceClutter(bare, models, options, rng);
  EXPECT_EQ(bare.items.size(), 1u);
}

TEST(SceneLayoutTest, LightComesFromAbove) {
  std::mt19937_64 rng(9);
  for (int i = 0; i < 20; ++i) {
    SceneLayout layout;
    SampleLight(layout, rng);
    EXPECT_NEAR(layout.light_to_world.norm(), 1.0, 1e-12);
    EXPECT_GE(layout.light_to_world.z(), std::cos(DegToRad(35.0)) - 1e-12);
    EXPECT_GE(layout.ambient, 0.3);
    EXPECT_LE(layout.ambient, 0.5);
  }
}

}  // namespace
}  // namespace layermod
