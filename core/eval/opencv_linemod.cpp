// SPDX-License-Identifier: MIT
#include "eval/opencv_linemod.h"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <opencv2/rgbd/linemod.hpp>
#include <set>

#include "pose/initial_pose.h"
#include "render/rasterizer.h"
#include "util/error.h"

namespace layermod {
namespace {

std::string ClassId(std::int32_t obj_id, int layer_index) {
  return "obj" + std::to_string(obj_id) + "_layer" + std::to_string(layer_index);
}

cv::Mat DepthAsUshortMm(const cv::Mat& depth_mm) {
  cv::Mat depth16;
  depth_mm.convertTo(depth16, CV_16U);  // rounds and saturates; 0 stays invalid
  return depth16;
}

// cv::linemod linearizes every pyramid level in steps of that level's T: the images must be
// multiples of T_l * 2^l. Pads with zeros (no gradient, no depth) on the right and bottom.
cv::Mat PadForLinemod(const cv::Mat& image, const std::vector<int>& spread_px) {
  int multiple = 1;
  for (std::size_t level = 0; level < spread_px.size(); ++level) {
    multiple = std::lcm(multiple, spread_px[level] << level);
  }
  const int bottom = (multiple - image.rows % multiple) % multiple;
  const int right = (multiple - image.cols % multiple) % multiple;
  if (bottom == 0 && right == 0) return image;
  cv::Mat padded;
  cv::copyMakeBorder(image, padded, 0, bottom, 0, right, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  return padded;
}

std::unique_ptr<cv::linemod::Detector> MakeDetector(const FeatureOptions& features,
                                                    bool use_depth) {
  std::vector<cv::Ptr<cv::linemod::Modality>> modalities;
  modalities.push_back(cv::makePtr<cv::linemod::ColorGradient>(
      features.weak_gradient, static_cast<std::size_t>(features.color_features),
      features.strong_gradient));
  if (use_depth) {
    // OpenCV's defaults for the range (2 m) and the feature spacing (2 px).
    modalities.push_back(cv::makePtr<cv::linemod::DepthNormal>(
        2000, static_cast<int>(features.max_normal_depth_step_mm),
        static_cast<std::size_t>(features.normal_features), 2));
  }
  return std::make_unique<cv::linemod::Detector>(modalities, features.spread_px);
}

const FeatureOptions& SharedFeatures(const std::vector<const TemplateArchive*>& archives) {
  if (archives.empty() || archives.front()->manifest().objects.empty()) {
    throw Error("cv::linemod baseline: no archive object to train");
  }
  return archives.front()->manifest().objects.front().profile.features;
}

}  // namespace

void OpenCvLinemodOptions::Validate() const {
  if (!(threshold_percent > 0.0f && threshold_percent <= 100.0f)) {
    throw Error("cv::linemod threshold must be in (0, 100]");
  }
}

OpenCvLinemod::OpenCvLinemod(const std::vector<const TemplateArchive*>& archives,
                             const OpenCvLinemodOptions& options, const JobControl& job)
    : options_(options) {
  options_.Validate();
  spread_px_ = SharedFeatures(archives).spread_px;
  detector_ = MakeDetector(SharedFeatures(archives), options_.use_depth);
  std::size_t total = 0;
  for (const TemplateArchive* archive : archives) total += archive->templates().size();
  const auto start = std::chrono::steady_clock::now();
  std::size_t done = 0;
  for (const TemplateArchive* archive : archives) {
    for (std::size_t record = 0; record < archive->templates().size(); ++record) {
      job.ThrowIfCancelled();
      AddTemplate(*archive, record);
      job.Report(++done, total, "cv::linemod templates");
    }
  }
  training_.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

OpenCvLinemod::~OpenCvLinemod() = default;

void OpenCvLinemod::AddTemplate(const TemplateArchive& archive, std::size_t record_index) {
  const TemplateRecord& record = archive.templates()[record_index];
  if (record.status != TemplateStatus::kOk) {
    ++training_.refused;
    return;
  }
  const ArchiveObject& object = archive.Object(record.obj_id);
  const RenderedView view = RenderView(object.mesh, archive.camera(), record.cam_from_model);
  std::vector<cv::Mat> sources = {view.color};
  if (options_.use_depth) sources.push_back(DepthAsUshortMm(view.depth_mm));
  const std::string class_id = ClassId(record.obj_id, record.layer_index);
  cv::Rect box;
  const int template_id =
      view.empty() ? -1 : detector_->addTemplate(sources, class_id, view.mask, &box);
  if (template_id < 0) {
    ++training_.refused;
    return;
  }
  std::vector<ClassTemplate>& class_templates = classes_[class_id];
  class_templates.resize(static_cast<std::size_t>(template_id) + 1);
  class_templates[static_cast<std::size_t>(template_id)] =
      ClassTemplate{&archive, record_index, record.bbox_px.tl() - (view.roi.tl() + box.tl())};
  ++training_.templates;
  training_.template_ids.push_back(record.id);
}

Detection OpenCvLinemod::ToDetection(const ClassTemplate& entry, cv::Point match_tl,
                                     float similarity, const cv::Mat& depth_mm) const {
  const TemplateRecord& record = entry.archive->templates()[entry.record];
  const ArchiveObject& object = entry.archive->Object(record.obj_id);
  const cv::Point box_tl = match_tl + entry.box_offset_px;
  double centre_depth_mm = depth_mm.empty() ? 0.0 : EstimateCentreDepthMm(record, box_tl, depth_mm);
  if (centre_depth_mm <= 0.0) centre_depth_mm = record.layer_depth_mm;  // no depth there
  Detection detection;
  detection.obj_id = record.obj_id;
  detection.name = object.name;
  detection.score = similarity;
  detection.cam_from_model =
      PoseFromMatch(record, box_tl, centre_depth_mm, object.sphere.centre, entry.archive->camera());
  detection.template_id = record.id;
  detection.layer_index = record.layer_index;
  detection.layer_depth_mm = record.layer_depth_mm;
  detection.box_tl_px = box_tl;
  return detection;
}

std::vector<Detection> OpenCvLinemod::Detect(const cv::Mat& color, const cv::Mat& depth_mm) const {
  std::vector<cv::Mat> sources = {PadForLinemod(color, spread_px_)};
  if (options_.use_depth) {
    if (depth_mm.empty()) throw Error("cv::linemod with depth normals needs a depth image");
    sources.push_back(PadForLinemod(DepthAsUshortMm(depth_mm), spread_px_));
  }
  std::vector<cv::linemod::Match> matches;
  detector_->match(sources, options_.threshold_percent, matches);
  std::stable_sort(matches.begin(), matches.end(),
                   [](const cv::linemod::Match& a, const cv::linemod::Match& b) {
                     return a.similarity > b.similarity;
                   });
  std::vector<Detection> detections;
  std::set<std::int32_t> found;
  for (const cv::linemod::Match& match : matches) {
    const ClassTemplate& entry =
        classes_.at(match.class_id).at(static_cast<std::size_t>(match.template_id));
    if (!found.insert(entry.archive->templates()[entry.record].obj_id).second) continue;
    detections.push_back(ToDetection(entry, {match.x, match.y}, match.similarity,
                                     options_.use_depth ? depth_mm : cv::Mat()));
  }
  return detections;
}

}  // namespace layermod
