// SPDX-License-Identifier: MIT
#pragma once

// The baseline of `layermod bench`: OpenCV's cv::linemod (opencv_contrib rgbd) fed the same
// templates as our archive. Each archive template is rendered again at its stored pose with the
// archive's camera (colour, depth, mask) and added to a cv::linemod detector with the archive's
// feature counts, gradient thresholds and T; one class per object depth layer. A match's pose
// is the matched template's, placed at the scene depth (as our initial pose, before ICP).

#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pipeline/detector.h"
#include "templates/archive.h"
#include "util/job.h"

namespace cv::linemod {
class Detector;
}

namespace layermod {

struct OpenCvLinemodOptions {
  float threshold_percent = 80.0f;  // cv::linemod similarity a match needs
  bool use_depth = true;            // false: LINE-2D (colour gradients only)

  void Validate() const;  // throws Error
};

struct OpenCvLinemodTraining {
  int templates = 0;                        // added to cv::linemod
  std::vector<std::uint32_t> template_ids;  // their archive ids (TemplateRecord::id)
  int refused = 0;  // archive templates cv::linemod found too few features in (or weak ones)
  double seconds = 0.0;
};

class OpenCvLinemod {
 public:
  // Keeps a reference to `archives` (they must outlive this object). Reports progress per
  // template; throws Cancelled when `job` is cancelled.
  OpenCvLinemod(const std::vector<const TemplateArchive*>& archives,
                const OpenCvLinemodOptions& options, const JobControl& job = {});
  ~OpenCvLinemod();
  OpenCvLinemod(const OpenCvLinemod&) = delete;
  OpenCvLinemod& operator=(const OpenCvLinemod&) = delete;

  // The best match per object, best first. `color` BGR8; `depth_mm` CV_32F (ignored for LINE-2D),
  // both of the archives' camera size.
  std::vector<Detection> Detect(const cv::Mat& color, const cv::Mat& depth_mm) const;

  const OpenCvLinemodTraining& training() const { return training_; }

 private:
  // What a cv::linemod template id of a class stands for.
  struct ClassTemplate {
    const TemplateArchive* archive = nullptr;
    std::size_t record = 0;   // index in archive->templates()
    cv::Point box_offset_px;  // our template box top-left minus cv::linemod's
  };

  void AddTemplate(const TemplateArchive& archive, std::size_t record);
  Detection ToDetection(const ClassTemplate& entry, cv::Point match_tl, float similarity,
                        const cv::Mat& depth_mm) const;

  OpenCvLinemodOptions options_;
  std::vector<int> spread_px_;  // T per pyramid level
  std::unique_ptr<cv::linemod::Detector> detector_;
  std::map<std::string, std::vector<ClassTemplate>> classes_;
  OpenCvLinemodTraining training_;
};

}  // namespace layermod
