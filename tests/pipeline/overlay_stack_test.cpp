// SPDX-License-Identifier: MIT
#include "pipeline/overlay_stack.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "bracket_frame.h"
#include "pipeline/overlays.h"

namespace layermod {
namespace {

using test::BracketFrame;

cv::Mat Compose(const OverlayToggles& toggles) {
  const auto& frame = BracketFrame();
  return ComposeStageOverlays(frame.capture, frame.result, frame.detector, toggles);
}

int DifferentPixels(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  cv::Mat grey;
  cv::cvtColor(difference, grey, cv::COLOR_BGR2GRAY);
  return cv::countNonZero(grey);
}

TEST(OverlayStackTest, NothingShownGivesTheColourImage) {
  const cv::Mat composed = Compose({false, false, false, false});
  EXPECT_EQ(DifferentPixels(composed, BracketFrame().capture.color), 0);
}

TEST(OverlayStackTest, PosesAloneAreDrawnOnTheUndimmedImage) {
  const auto& frame = BracketFrame();
  cv::Mat expected = frame.capture.color.clone();
  DrawPoses(expected, frame.result.detections, frame.detector, frame.capture.camera);
  EXPECT_EQ(DifferentPixels(Compose({false, false, false, true}), expected), 0);
}

TEST(OverlayStackTest, RegionsAloneAreTheRegionPictureOnTheDimmedImage) {
  const auto& frame = BracketFrame();
  cv::Mat expected = frame.capture.color.clone();
  DimColor(expected);
  DrawRegionDivision(expected, frame.result.diagnostics.front(), frame.detector.Object(1));
  DrawLayerLegend(expected, frame.detector.Object(1));
  EXPECT_EQ(DifferentPixels(Compose({true, false, false, false}), expected), 0);
}

TEST(OverlayStackTest, TheCoarseLegendSitsBelowTheLayerLegend) {
  const auto& frame = BracketFrame();
  const int layers = static_cast<int>(frame.detector.Object(1).layer_depths_mm.size());
  const int legend_bottom = 6 + 18 * layers;
  const cv::Mat regions = Compose({true, false, false, false});
  const cv::Mat both = Compose({true, true, false, false});
  // The coarse legend is a line of text from the left edge just below the layer legend.
  const cv::Rect coarse_legend(0, legend_bottom, 200, 24);
  EXPECT_GT(DifferentPixels(both(coarse_legend), regions(coarse_legend)), 50);
  const cv::Mat coarse_only = Compose({false, true, false, false});
  const cv::Rect top_line(0, 0, 200, 24);
  EXPECT_GT(DifferentPixels(coarse_only(top_line), both(top_line)), 50);
}

TEST(OverlayStackTest, EveryStageAddsMarksToTheSameCanvas) {
  const cv::Mat all = Compose({});
  for (const OverlayToggles& one_off :
       {OverlayToggles{false, true, true, true}, OverlayToggles{true, false, true, true},
        OverlayToggles{true, true, false, true}, OverlayToggles{true, true, true, false}}) {
    EXPECT_GT(DifferentPixels(all, Compose(one_off)), 0);
  }
}

}  // namespace
}  // namespace layermod
