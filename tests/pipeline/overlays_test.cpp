// SPDX-License-Identifier: MIT
#include "pipeline/overlays.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "bracket_frame.h"

namespace layermod {
namespace {

using test::BracketFrame;

cv::Mat Dimmed(const cv::Mat& color) {
  cv::Mat canvas = color.clone();
  DimColor(canvas);
  return canvas;
}

// CV_8U, 255 where `a` and `b` differ.
cv::Mat Changed(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  cv::Mat grey;
  cv::cvtColor(difference, grey, cv::COLOR_BGR2GRAY);
  return grey > 0;
}

int ChangedIn(const cv::Mat& changed, const cv::Rect& area) {
  return cv::countNonZero(changed(area & cv::Rect(0, 0, changed.cols, changed.rows)));
}

const ObjectDiagnostics& BracketDiagnostics() { return BracketFrame().result.diagnostics.front(); }

TEST(OverlaysTest, DimColorDarkensEveryPixelInPlace) {
  cv::Mat canvas(4, 5, CV_8UC3, cv::Scalar(100, 200, 50));
  DimColor(canvas);
  EXPECT_EQ(canvas.size(), cv::Size(5, 4));
  EXPECT_EQ(canvas.at<cv::Vec3b>(3, 4), cv::Vec3b(60, 120, 30));
}

TEST(OverlaysTest, RegionDivisionTintsTheBlocksAndNothingElse) {
  const cv::Mat base = Dimmed(BracketFrame().capture.color);
  cv::Mat canvas = base.clone();
  const ObjectDiagnostics& diagnostics = BracketDiagnostics();
  ASSERT_FALSE(diagnostics.division.blocks.empty());
  DrawRegionDivision(canvas, diagnostics, BracketFrame().detector.Object(1));
  cv::Rect blocks;
  for (const SceneBlock& block : diagnostics.division.blocks) blocks |= block.bbox_px;
  const cv::Mat changed = Changed(canvas, base);
  EXPECT_GT(ChangedIn(changed, blocks), blocks.area() / 4);
  EXPECT_EQ(cv::countNonZero(changed), ChangedIn(changed, blocks));
}

TEST(OverlaysTest, LegendsFillTheRowsTheyReturn) {
  const ArchiveObject& object = BracketFrame().detector.Object(1);
  const int layers = static_cast<int>(object.layer_depths_mm.size());
  const cv::Mat base = Dimmed(BracketFrame().capture.color);
  cv::Mat canvas = base.clone();
  const int below_layers = DrawLayerLegend(canvas, object, 10);
  EXPECT_EQ(below_layers, 10 + 6 + 18 * layers);
  const int below_coarse = DrawCoarseLegend(canvas, below_layers);
  EXPECT_EQ(below_coarse, below_layers + 24);
  const cv::Mat changed = Changed(canvas, base);
  EXPECT_EQ(ChangedIn(changed, {0, 0, canvas.cols, 10}), 0);
  EXPECT_GT(ChangedIn(changed, {0, 10, canvas.cols, below_layers - 10}), 0);
  EXPECT_GT(ChangedIn(changed, {0, below_layers, canvas.cols, below_coarse - below_layers}), 0);
  EXPECT_EQ(ChangedIn(changed, {0, below_coarse, canvas.cols, canvas.rows}), 0);
}

TEST(OverlaysTest, CoarsePositioningMarksTheEvaluatedPoints) {
  const cv::Mat base = Dimmed(BracketFrame().capture.color);
  cv::Mat canvas = base.clone();
  const ObjectDiagnostics& diagnostics = BracketDiagnostics();
  ASSERT_FALSE(diagnostics.coarse.evaluated.empty());
  DrawCoarsePositioning(canvas, diagnostics);
  const cv::Point point = diagnostics.coarse.evaluated.front().points.front().pixel;
  EXPECT_NE(canvas.at<cv::Vec3b>(point), base.at<cv::Vec3b>(point));
}

TEST(OverlaysTest, MatchesOutlineTheBestTemplateWhereItMatched) {
  const cv::Mat base = Dimmed(BracketFrame().capture.color);
  cv::Mat canvas = base.clone();
  const ObjectDiagnostics& diagnostics = BracketDiagnostics();
  ASSERT_FALSE(diagnostics.matches.empty());
  const TemplateArchive& archive = BracketFrame().detector.ArchiveOf(1);
  DrawMatches(canvas, diagnostics, archive);
  const RawMatch& best = diagnostics.matches.front();
  EXPECT_EQ(canvas.at<cv::Vec3b>(best.y, best.x + 1), cv::Vec3b(0, 255, 0));  // top edge, green
  ObjectDiagnostics none;
  cv::Mat untouched = base.clone();
  DrawMatches(untouched, none, archive);
  EXPECT_EQ(cv::countNonZero(Changed(untouched, base)), 0);
}

TEST(OverlaysTest, PosesDrawTheContourAtTheDetectedPoseOnly) {
  const auto& frame = BracketFrame();
  ASSERT_FALSE(frame.result.detections.empty());
  cv::Mat canvas = frame.capture.color.clone();
  DrawPoses(canvas, frame.result.detections, frame.detector, frame.capture.camera);
  const Detection& best = frame.result.detections.front();
  const ArchiveObject& object = frame.detector.Object(best.obj_id);
  const Eigen::Vector2d centre =
      frame.capture.camera.Project(best.cam_from_model * object.sphere.centre);
  const double radius_px =
      frame.capture.camera.fx * object.sphere.radius_mm / best.cam_from_model.t.z();
  const int reach = static_cast<int>(radius_px) + 4;
  const cv::Rect around(static_cast<int>(centre.x()) - reach, static_cast<int>(centre.y()) - reach,
                        2 * reach, 2 * reach);
  const cv::Mat changed = Changed(canvas, frame.capture.color);
  EXPECT_GT(ChangedIn(changed, around), 20);
  // Besides the contour and axes only the label (above the centre, moved left where it would
  // leave the image) is drawn.
  const cv::Rect label(0, around.y - 30, canvas.cols, around.height + 30);
  EXPECT_EQ(cv::countNonZero(changed), ChangedIn(changed, label));
}

TEST(OverlaysTest, LayerColoursRunFromRedTowardsMagenta) {
  EXPECT_EQ(LayerColor(0, 3), cv::Scalar(35, 35, 255));   // hue 0: red (BGR)
  EXPECT_EQ(LayerColor(2, 3), cv::Scalar(255, 35, 255));  // hue 150 (of 180): magenta
  EXPECT_NE(LayerColor(1, 3), LayerColor(2, 3));
  EXPECT_EQ(LayerColor(0, 1), LayerColor(0, 3));  // one layer: no division by zero
}

}  // namespace
}  // namespace layermod
