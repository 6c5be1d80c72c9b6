// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "pipeline/detector.h"

namespace layermod {

// Which of the detector's stage pictures are laid over the capture.
struct OverlayToggles {
  bool regions = true;  // region division, blocks tinted by depth layer
  bool coarse = true;   // detection points kept / rejected
  bool matches = true;  // raw template matches
  bool poses = true;    // final poses: model contour and axes

  bool any_stage() const { return regions || coarse || matches; }
};

// The capture's colour image with the enabled stage pictures (overlays.h) stacked in pipeline
// order on one canvas (BGR8), dimmed once when any stage before the poses is shown. The legends
// stack below one another, and match labels that would overlap a better match's or a pose's
// label are left out. The studio's detection preview.
cv::Mat ComposeStageOverlays(const Capture& capture, const DetectionResult& result,
                             const Detector& detector, const OverlayToggles& toggles);

}  // namespace layermod
