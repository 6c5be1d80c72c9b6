// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>

#include "pipeline/detector.h"

namespace layermod::ui {

// Which of the detector's stage pictures the preview lays over the capture.
struct OverlayToggles {
  bool regions = true;  // region division, blocks tinted by depth layer
  bool coarse = true;   // detection points kept / rejected
  bool matches = true;  // raw template matches
  bool poses = true;    // final poses: model contour and axes

  bool any_stage() const { return regions || coarse || matches; }
};

// The capture's colour image with the enabled overlays stacked in pipeline order (BGR8). The
// pictures are the core's (pipeline/overlays.h), so the studio and `layermod detect
// --overlay-stages` agree; each is drawn alone over the dimmed colour image and only the pixels
// it changed are kept, so they combine without dimming twice.
cv::Mat ComposeDetectionOverlays(const Capture& capture, const DetectionResult& result,
                                 const Detector& detector, const OverlayToggles& toggles);

}  // namespace layermod::ui
