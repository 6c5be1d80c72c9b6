// SPDX-License-Identifier: MIT
// A part whose mesh has -Z up (as some CAD exports and the original LineMOD meshes do), standing
// on a table as it is used: trained with --up-axis -z and the default envelope it is found; the
// same envelope measured from +Z looks at it from under the table and is not enough. Runs on the
// bundled sample bracket, so it needs no external data.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "dataset/bop.h"
#include "eval/pose_metrics.h"
#include "geometry/camera.h"
#include "geometry/up_axis.h"
#include "mesh/model.h"
#include "mesh/sample_part.h"
#include "pipeline/detector.h"
#include "pipeline/training.h"
#include "support/test_paths.h"
#include "synth/synthesizer.h"

namespace layermod {
namespace {

constexpr std::int32_t kBracket = 1;
constexpr int kScenes = 12;

// The sample bracket turned upside down in its own frame: its real top is the mesh's -Z.
std::filesystem::path WriteMinusZUpBracket(const std::filesystem::path& path) {
  TriMesh mesh = MakeSampleBracket();
  const Eigen::Matrix3f flip = UprightFromUpAxis("-z").cast<float>();
  for (const auto vertex : mesh.vertices()) {
    const TriMesh::Point& p = mesh.point(vertex);
    const Eigen::Vector3f q = flip * Eigen::Vector3f(p[0], p[1], p[2]);
    mesh.set_point(vertex, TriMesh::Point(q.x(), q.y(), q.z()));
    if (mesh.has_vertex_normals()) {
      const TriMesh::Normal& n = mesh.normal(vertex);
      const Eigen::Vector3f m = flip * Eigen::Vector3f(n[0], n[1], n[2]);
      mesh.set_normal(vertex, TriMesh::Normal(m.x(), m.y(), m.z()));
    }
  }
  SaveModelPly(path, mesh);
  return path;
}

class UpAxisDetectionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    camera_ = LoadCameraJson(test::SourceDir() / "resources/sample/camera.json");
    mesh_path_ = WriteMinusZUpBracket(dir_ / "bracket_minus_z.ply");
  }

  std::filesystem::path SynthesizeStandingScenes() const {
    SynthOptions options;
    options.models_dir = mesh_path_;
    options.obj_ids = {kBracket};
    options.scenes = kScenes;
    options.seed = 21;
    options.dmin_mm = 700.0;
    options.dmax_mm = 800.0;
    options.roll_max_deg = 30.0;
    options.clutter = 1;
    options.upright_from_model = UprightFromUpAxis("-z");  // it stands on its real base
    options.camera = camera_;
    options.out_dir = dir_ / "synth";
    SynthesizeScenes(options);
    return dir_ / "synth" / "test";
  }

  // The default envelope (upper hemisphere, roll within +-45) measured from `up_axis`, thinned
  // to keep the test short.
  Detector Train(const std::string& up_axis) const {
    TrainingRequest request;
    request.obj_id = kBracket;
    request.name = "bracket";
    request.camera = camera_;
    request.profile.depth_min_mm = 650.0;
    request.profile.depth_max_mm = 850.0;
    request.profile.views.even_spacing_deg = 12.0;
    request.profile.views.roll = {-30.0, 15.0, 30.0};
    request.profile.views.upright_from_model = UprightFromUpAxis(up_axis);
    return Detector({TrainTemplates(LoadModel(mesh_path_), request).archive});
  }

  int CorrectPoses(const Detector& detector, const std::filesystem::path& scenes) const {
    const ArchiveObject& object = detector.Object(kBracket);
    std::vector<Eigen::Vector3d> points;
    for (const Eigen::Vector3f& vertex : object.mesh.positions)
      points.push_back(vertex.cast<double>());
    // The best pose whatever its confidence: the question is whether templates from the right
    // side exist, not whether a coarse test archive's poses verify above the default acceptance.
    DetectorOptions options;
    options.min_confidence = 0.0;
    int correct = 0;
    for (const BopScene& scene : ListBopScenes(scenes)) {
      for (int image_id : scene.image_ids) {
        const BopFrame frame = LoadBopFrame(scene, image_id);
        const DetectionResult result =
            detector.Detect({frame.color, frame.depth_mm, frame.camera}, options);
        if (result.detections.empty()) continue;
        const double add_mm = AddErrorMm(points, result.detections.front().cam_from_model,
                                         frame.gt.front().cam_from_model);
        correct += add_mm <= 0.1 * object.diameter_mm ? 1 : 0;
      }
    }
    return correct;
  }

  test::TempDir dir_;
  PinholeCamera camera_;
  std::filesystem::path mesh_path_;
};

TEST_F(UpAxisDetectionTest, MinusZUpPartIsFoundWithItsUpAxis) {
  const std::filesystem::path scenes = SynthesizeStandingScenes();
  const int with_up_axis = CorrectPoses(Train("-z"), scenes);
  const int from_below = CorrectPoses(Train("+z"), scenes);
  RecordProperty("correct_with_up_axis", with_up_axis);
  RecordProperty("correct_from_below", from_below);
  // Measured 11 of 12 with the up axis (10 of 12 with seed 22), 0 of 12 from below; 7 leaves
  // room for platform differences in floating point, not for a regression.
  EXPECT_GE(with_up_axis, 7) << with_up_axis << " of " << kScenes << " within ADD 0.1 d";
  EXPECT_LE(from_below, 2) << "from below: " << from_below;
}

}  // namespace
}  // namespace layermod
