// SPDX-License-Identifier: MIT
#include "features/extraction.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "features/candidates.h"
#include "features/depth_edges.h"
#include "features/feature_selection.h"
#include "features/pyramid.h"
#include "features/quantize.h"
#include "util/error.h"

namespace layermod {
namespace {

// Colour candidates may lie this far outside the mask: the silhouette's gradient against the
// black background peaks on the boundary, half of it on background pixels.
constexpr int kSilhouetteDilationPx = 1;
// Normal candidates stay this far inside the mask: near the silhouette, scene normals mix object
// and background depth.
constexpr int kInteriorErosionPx = 2;
// Coarser levels keep count / 2^k features, but never fewer than this.
constexpr int kMinLevelFeatures = 8;

// One pyramid level of the view; pixel (0, 0) is camera pixel `offset_px` of that level.
struct LevelImages {
  cv::Mat color;  // CV_8UC3, may be empty (no colour modality)
  cv::Mat depth_mm;
  cv::Mat mask;
  cv::Point offset_px;
  PinholeCamera camera;
};

void CheckView(const RenderedView& view) {
  const cv::Size size = view.roi.size();
  if (view.depth_mm.type() != CV_32F || view.depth_mm.size() != size) {
    throw Error("ExtractTemplate: view depth must be CV_32F of the roi size");
  }
  if (view.mask.type() != CV_8U || view.mask.size() != size) {
    throw Error("ExtractTemplate: view mask must be CV_8U of the roi size");
  }
  if (!view.color.empty() && (view.color.type() != CV_8UC3 || view.color.size() != size)) {
    throw Error("ExtractTemplate: view colour must be CV_8UC3 of the roi size");
  }
}

// Level 0 padded with background so that its top-left corner is a multiple of 2^(levels - 1):
// then pixel u of level k is exactly camera pixel (offset >> k) + u.
LevelImages AlignedLevel0(const RenderedView& view, const PinholeCamera& camera, int levels) {
  const int alignment = 1 << (levels - 1);
  const int pad_x = view.roi.x & (alignment - 1);
  const int pad_y = view.roi.y & (alignment - 1);
  LevelImages level;
  level.offset_px = {view.roi.x - pad_x, view.roi.y - pad_y};
  level.camera = camera;
  auto pad = [&](const cv::Mat& image) {
    cv::Mat padded;
    cv::copyMakeBorder(image, padded, pad_y, 0, pad_x, 0, cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return padded;
  };
  level.depth_mm = pad(view.depth_mm);
  level.mask = pad(view.mask);
  if (!view.color.empty()) level.color = pad(view.color);
  return level;
}

LevelImages NextLevel(const LevelImages& level, const PinholeCamera& camera, int k) {
  LevelImages next;
  next.color = level.color.empty() ? cv::Mat() : DownsampleColor(level.color);
  next.depth_mm = DownsampleNearest(level.depth_mm);
  next.mask = DownsampleNearest(level.mask);
  next.offset_px = {level.offset_px.x / 2, level.offset_px.y / 2};
  next.camera = PyramidLevelCamera(camera, k);
  return next;
}

std::vector<FeatureCandidate> ColorCandidates(const LevelImages& level,
                                              const FeatureOptions& options) {
  if (level.color.empty()) return {};
  cv::Mat region;
  cv::dilate(level.mask, region, cv::Mat(), cv::Point(-1, -1), kSilhouetteDilationPx);
  return ColorGradientCandidates(level.color, region, level.offset_px, options.weak_gradient,
                                 options.strong_gradient);
}

// Normals are computed only around the eroded mask.
std::vector<FeatureCandidate> NormalCandidates(const LevelImages& level, int count,
                                               const FeatureOptions& options) {
  cv::Mat interior;
  cv::erode(level.mask, interior, cv::Mat(), cv::Point(-1, -1), kInteriorErosionPx,
            cv::BORDER_CONSTANT, cv::Scalar(0));
  const cv::Rect box = cv::boundingRect(interior);
  if (box.area() == 0) return {};
  // The 5x5 fit of a box pixel reads 2 pixels around it; label borders need 1 more.
  const cv::Rect window =
      cv::Rect(box.x - 3, box.y - 3, box.width + 6, box.height + 6) & cv::Rect({}, interior.size());
  return DepthNormalCandidates(level.depth_mm(window), interior(window), level.camera,
                               level.offset_px + window.tl(), options.max_normal_depth_step_mm,
                               options.normal_frame, count);
}

int LevelCount(int level0_count, int k) {
  if (level0_count <= 0) return 0;
  return std::max(level0_count >> k, std::min(level0_count, kMinLevelFeatures));
}

// Features of one level in that level's camera pixels.
std::vector<Feature> LevelFeatures(const LevelImages& level, int k, const FeatureOptions& options) {
  std::vector<Feature> features;
  const int color_count = LevelCount(options.color_features, k);
  const int normal_count = LevelCount(options.normal_features, k);
  if (color_count > 0) {
    features = SelectScatteredFeatures(ColorCandidates(level, options), color_count,
                                       Modality::kColorGradient);
  }
  if (normal_count > 0) {
    const std::vector<Feature> normals = SelectScatteredFeatures(
        NormalCandidates(level, normal_count, options), normal_count, Modality::kDepthNormal);
    features.insert(features.end(), normals.begin(), normals.end());
  }
  return features;
}

// Bounding box (level-0 camera pixels) of every level's features scaled to level 0.
cv::Rect FeatureBox(const std::vector<TemplateLevel>& levels) {
  int min_x = INT_MAX, min_y = INT_MAX, max_x = INT_MIN, max_y = INT_MIN;
  for (const TemplateLevel& level : levels) {
    for (const Feature& f : level.features) {
      min_x = std::min(min_x, f.x << level.pyramid_level);
      min_y = std::min(min_y, f.y << level.pyramid_level);
      max_x = std::max(max_x, f.x << level.pyramid_level);
      max_y = std::max(max_y, f.y << level.pyramid_level);
    }
  }
  if (min_x > max_x) return {};
  return {min_x, min_y, max_x - min_x + 1, max_y - min_y + 1};
}

// Moves every level's features to its box corner (bbox.tl() >> k) and sets the box size.
void MakeRelative(const cv::Rect& bbox_px, std::vector<TemplateLevel>* levels) {
  for (TemplateLevel& level : *levels) {
    const int k = level.pyramid_level;
    const int x0 = bbox_px.x >> k, y0 = bbox_px.y >> k;
    level.width = ((bbox_px.x + bbox_px.width - 1) >> k) - x0 + 1;
    level.height = ((bbox_px.y + bbox_px.height - 1) >> k) - y0 + 1;
    for (Feature& f : level.features) {
      f.x = static_cast<std::int16_t>(f.x - x0);
      f.y = static_cast<std::int16_t>(f.y - y0);
    }
  }
}

}  // namespace

int ExtractedTemplate::FeatureCount(int level) const {
  if (level < 0 || level >= static_cast<int>(levels.size())) return 0;
  return static_cast<int>(levels[level].features.size());
}

ExtractedTemplate ExtractTemplate(const RenderedView& view, const PinholeCamera& camera,
                                  const FeatureOptions& options) {
  options.Validate();
  camera.Validate();
  ExtractedTemplate result;
  result.levels.resize(options.pyramid_levels);
  for (int k = 0; k < options.pyramid_levels; ++k) result.levels[k].pyramid_level = k;
  if (view.roi.area() == 0) return result;
  CheckView(view);
  if (cv::countNonZero(view.mask) == 0) return result;
  LevelImages level = AlignedLevel0(view, camera, options.pyramid_levels);
  for (int k = 0; k < options.pyramid_levels; ++k) {
    if (k > 0) level = NextLevel(level, camera, k);
    result.levels[k].features = LevelFeatures(level, k, options);
  }
  result.bbox_px = FeatureBox(result.levels);
  if (result.bbox_px.area() > 0) MakeRelative(result.bbox_px, &result.levels);
  return result;
}
}  // namespace layermod
