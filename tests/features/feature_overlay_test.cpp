// SPDX-License-Identifier: MIT
#include "features/feature_overlay.h"

#include <gtest/gtest.h>

#include "features/synthetic_views.h"

namespace layermod {
namespace {

ExtractedTemplate OneOfEach(const cv::Rect& bbox_px) {
  ExtractedTemplate tmpl;
  tmpl.bbox_px = bbox_px;
  tmpl.levels.resize(1);
  tmpl.levels[0].features = {{10, 10, 4, Modality::kColorGradient},
                             {30, 20, 2, Modality::kDepthNormal}};
  return tmpl;
}

TEST(RenderFeatureOverlayTest, DrawsFeaturesAtTheirPixelsOverTheColourImage) {
  const RenderedView view = test::DiscView({200, 100, 80, 60}, {240.0, 130.0}, 25.0, 700.0f);
  const ExtractedTemplate tmpl = OneOfEach({205, 102, 40, 30});
  const cv::Mat overlay = RenderFeatureOverlay(view, tmpl);
  ASSERT_EQ(overlay.type(), CV_8UC3);
  ASSERT_EQ(overlay.size(), view.roi.size());
  // Features are relative to bbox_px; the overlay starts at roi.tl(): offset (5, 2).
  EXPECT_EQ(overlay.at<cv::Vec3b>(12, 15), cv::Vec3b(0, 255, 0));  // colour feature: green
  EXPECT_EQ(overlay.at<cv::Vec3b>(22, 35), cv::Vec3b(0, 0, 255));  // normal feature: red
  EXPECT_EQ(overlay.at<cv::Vec3b>(30, 60), view.color.at<cv::Vec3b>(30, 60));  // untouched
}

TEST(RenderFeatureOverlayTest, BlackColourFallsBackToGreySilhouette) {
  RenderedView view = test::DiscView({200, 100, 80, 60}, {240.0, 130.0}, 25.0, 700.0f);
  view.color.setTo(0);
  const cv::Mat overlay = RenderFeatureOverlay(view, ExtractedTemplate{});
  const cv::Vec3b& inside = overlay.at<cv::Vec3b>(30, 40);
  EXPECT_GT(inside[0], 50);
  EXPECT_EQ(inside[0], inside[1]);
  EXPECT_EQ(overlay.at<cv::Vec3b>(2, 2), cv::Vec3b(0, 0, 0));
}

TEST(RenderFeatureOverlayTest, RealTemplateMarksEveryFeature) {
  const RenderedView view = test::PyramidView({301, 171, 150, 150}, {376, 246}, 55, 800.0f, 60.0f);
  const ExtractedTemplate tmpl = ExtractTemplate(view, test::KinectCamera(), FeatureOptions{});
  const cv::Mat overlay = RenderFeatureOverlay(view, tmpl);
  for (const Feature& f : tmpl.levels[0].features) {
    const cv::Point at = tmpl.bbox_px.tl() + cv::Point(f.x, f.y) - view.roi.tl();
    const cv::Vec3b expected =
        f.modality == Modality::kColorGradient ? cv::Vec3b(0, 255, 0) : cv::Vec3b(0, 0, 255);
    EXPECT_EQ(overlay.at<cv::Vec3b>(at), expected);
  }
}

}  // namespace
}  // namespace layermod
