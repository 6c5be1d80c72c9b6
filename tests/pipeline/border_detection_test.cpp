// SPDX-License-Identifier: MIT
// A part the image's border cuts: its templates are placed reaching past the image, where the
// region's padding hides their features (PrepareSceneRegion, match/occluders.h).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "eval_fixtures.h"
#include "pipeline/detector.h"
#include "render/rasterizer.h"

namespace layermod {
namespace {

// The whole frame turned about the camera's centre so that the part's centre is seen at
// `centre_px`: the template's view, as PoseFromMatch places it there.
Pose SeenAt(const Pose& pose, const Eigen::Vector3d& model_centre, const PinholeCamera& camera,
            const Eigen::Vector2d& centre_px) {
  const Eigen::Vector3d from = (pose * model_centre).normalized();
  const Eigen::Vector3d to = camera.Backproject(centre_px, 1.0).normalized();
  const Eigen::Matrix3d turn = Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
  return Pose{turn * pose.R, turn * pose.t};
}

struct CutFrame {
  Capture capture;
  Pose truth;
  double visible_share = 0.0;  // of the part's silhouette, inside the image
};

// The bracket at the middle template's view, its centre `inside_px` from the image's left edge,
// in front of a wall 150 mm behind it.
CutFrame BracketCutByTheLeftBorder(const TemplateArchive& archive, double inside_px) {
  const TemplateRecord& record = archive.templates()[archive.templates().size() / 2];
  const PinholeCamera& camera = archive.camera();
  const ArchiveObject& object = archive.Object(record.obj_id);
  CutFrame frame;
  frame.truth =
      SeenAt(record.cam_from_model, object.sphere.centre, camera, {inside_px, camera.height / 2.0});
  // The silhouette on a canvas three images wide, to count what the image keeps of it.
  PinholeCamera canvas = camera;
  canvas.width *= 3;
  canvas.cx += camera.width;
  const RenderedView whole = RenderView(object.mesh, canvas, frame.truth);
  const cv::Rect image(camera.width, 0, camera.width, camera.height);
  const int kept = cv::countNonZero(whole.mask((whole.roi & image) - whole.roi.tl()));
  frame.visible_share = static_cast<double>(kept) / cv::countNonZero(whole.mask);

  const RenderedView view = RenderView(object.mesh, camera, frame.truth);
  frame.capture.camera = camera;
  frame.capture.color = cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar(70, 80, 90));
  frame.capture.depth_mm =
      cv::Mat(camera.height, camera.width, CV_32F, cv::Scalar(record.layer_depth_mm + 150.0));
  view.color.copyTo(frame.capture.color(view.roi), view.mask);
  view.depth_mm.copyTo(frame.capture.depth_mm(view.roi), view.mask);
  return frame;
}

TEST(BorderDetectionTest, FindsAPartTheImageBorderCuts) {
  const TemplateArchive archive = test::TrainBracketArchive(650.0, 750.0);
  const CutFrame frame = BracketCutByTheLeftBorder(archive, 4.0);
  ASSERT_GT(frame.visible_share, 0.5);
  ASSERT_LT(frame.visible_share, 0.85);
  const Detector detector({archive});
  DetectorOptions options;
  options.min_confidence = 0.0;
  const DetectionResult result = detector.Detect(frame.capture, options);
  ASSERT_FALSE(result.detections.empty());
  const Detection& best = result.detections.front();
  EXPECT_LT(best.box_tl_px.x, 0);  // the template reaches past the image
  EXPECT_LT((best.cam_from_model.t - frame.truth.t).norm(), 10.0);
  const Eigen::AngleAxisd turn(best.cam_from_model.R.transpose() * frame.truth.R);
  EXPECT_LT(RadToDeg(turn.angle()), 5.0);
}

}  // namespace
}  // namespace layermod
