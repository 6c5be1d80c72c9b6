// SPDX-License-Identifier: MIT
#include "eval/envelope_coverage.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/camera.h"
#include "geometry/up_axis.h"
#include "geometry/views.h"
#include "mesh/model.h"
#include "pipeline/training.h"
#include "support/test_paths.h"

namespace layermod {
namespace {

// The bundled bracket over 600-800 mm, upper hemisphere every 20 deg, roll -30..30.
TemplateArchive TrainBracket(const std::string& up_axis) {
  TrainingRequest request;
  request.obj_id = 3;
  request.name = "bracket";
  request.camera = LoadCameraJson(test::SourceDir() / "resources/sample/camera.json");
  request.profile.depth_min_mm = 600.0;
  request.profile.depth_max_mm = 800.0;
  request.profile.views.even_spacing_deg = 20.0;
  request.profile.views.roll = {-30.0, 15.0, 30.0};
  request.profile.views.upright_from_model = UprightFromUpAxis(up_axis);
  return TrainTemplates(LoadModel(test::SourceDir() / "resources/sample/bracket.ply"), request)
      .archive;
}

class EnvelopeCoverageTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { archive_ = new TemplateArchive(TrainBracket("+z")); }
  static void TearDownTestSuite() { delete archive_; }

  Pose ViewPose(double azimuth, double elevation, double roll, double depth_mm) const {
    const ArchiveObject& object = archive_->Object(3);
    return CamFromModelForView({azimuth, elevation, roll}, object.sphere.centre, depth_mm);
  }

  static TemplateArchive* archive_;
};
TemplateArchive* EnvelopeCoverageTest::archive_ = nullptr;

TEST_F(EnvelopeCoverageTest, EveryTemplatePoseIsInside) {
  const ViewEnvelope envelope(*archive_, 3);
  EXPECT_GT(envelope.view_step_deg(), 10.0);
  EXPECT_LT(envelope.view_step_deg(), 30.0);
  for (const TemplateRecord& tmpl : archive_->TemplatesOf(3)) {
    const EnvelopeCheck check = envelope.Check(tmpl.cam_from_model);
    ASSERT_TRUE(check.inside) << check.reason;
    EXPECT_NEAR(check.view_gap_deg, 0.0, 1e-6);
    EXPECT_NEAR(check.roll_deg, tmpl.view.roll_deg, 1e-6);
    EXPECT_NEAR(check.depth_mm, tmpl.layer_depth_mm, 1e-3);
  }
}

TEST_F(EnvelopeCoverageTest, AnOffCentreObjectIsSeenFromTheSameView) {
  const ViewEnvelope envelope(*archive_, 3);
  Pose pose = ViewPose(40.0, 45.0, 10.0, 700.0);
  pose.t += Eigen::Vector3d(150.0, -90.0, 0.0);  // the part near the image corner
  const EnvelopeCheck check = envelope.Check(pose);
  EXPECT_TRUE(check.inside) << check.reason;
  EXPECT_LT(check.view_gap_deg, envelope.view_step_deg());
  // The view it is seen from, as the studio draws its camera among the template cameras.
  const EnvelopeCheck centred = envelope.Check(ViewPose(40.0, 45.0, 10.0, 700.0));
  EXPECT_NEAR(centred.azimuth_deg, 40.0, 1e-6);
  EXPECT_NEAR(centred.elevation_deg, 45.0, 1e-6);
}

TEST_F(EnvelopeCoverageTest, PosesBeyondTheEnvelopeAreNamed) {
  const ViewEnvelope envelope(*archive_, 3);
  const EnvelopeCheck below = envelope.Check(ViewPose(0.0, -60.0, 0.0, 700.0));
  EXPECT_FALSE(below.inside);
  EXPECT_NE(below.reason.find("seen from -60 deg elevation"), std::string::npos) << below.reason;
  const EnvelopeCheck rolled = envelope.Check(ViewPose(0.0, 45.0, 100.0, 700.0));
  EXPECT_FALSE(rolled.inside);
  EXPECT_NE(rolled.reason.find("roll 100 deg"), std::string::npos) << rolled.reason;
  const EnvelopeCheck far = envelope.Check(ViewPose(0.0, 45.0, 0.0, 1500.0));
  EXPECT_FALSE(far.inside);
  EXPECT_NE(far.reason.find("depth 1500 mm"), std::string::npos) << far.reason;
  // Just beyond the last layer by less than a layer spacing still counts as covered.
  EXPECT_TRUE(envelope.Check(ViewPose(0.0, 45.0, 0.0, 810.0)).inside);
}

TEST_F(EnvelopeCoverageTest, AFramesGroundTruthIsCheckedPerInstance) {
  const std::vector<BopGroundTruth> ground_truth = {{3, ViewPose(10.0, 50.0, 0.0, 700.0)},
                                                    {9, ViewPose(10.0, 50.0, 0.0, 700.0)},
                                                    {3, ViewPose(0.0, -60.0, 0.0, 700.0)}};
  const std::vector<GroundTruthCoverage> coverage = ObjectEnvelopes(*archive_).Check(ground_truth);
  ASSERT_EQ(coverage.size(), 3u);
  EXPECT_EQ(coverage[0].obj_id, 3);
  ASSERT_TRUE(coverage[0].check.has_value());
  EXPECT_TRUE(coverage[0].check->inside);
  EXPECT_EQ(coverage[1].obj_id, 9);
  EXPECT_FALSE(coverage[1].check.has_value());  // no templates of object 9
  ASSERT_TRUE(coverage[2].check.has_value());
  EXPECT_FALSE(coverage[2].check->inside);
}

TEST(EnvelopeCoverageUpAxisTest, TheEnvelopeFollowsTheUpAxis) {
  const TemplateArchive archive = TrainBracket("-z");
  const ViewEnvelope envelope(archive, 3);
  const ArchiveObject& object = archive.Object(3);
  // Above the -Z-up part is below its mesh's XY plane.
  const Pose from_its_top =
      CamFromModelForView({30.0, 50.0, 0.0}, object.sphere.centre, 700.0, UprightFromUpAxis("-z"));
  const Pose from_mesh_top = CamFromModelForView({30.0, 50.0, 0.0}, object.sphere.centre, 700.0);
  EXPECT_TRUE(envelope.Check(from_its_top).inside);
  EXPECT_FALSE(envelope.Check(from_mesh_top).inside);
}

}  // namespace
}  // namespace layermod
