// SPDX-License-Identifier: MIT
// One detected frame of the bundled bracket, shared by the overlay and detector tests.
#pragma once

#include "pipeline/detector.h"

namespace layermod::test {

struct DetectedBracketFrame {
  Detector detector;       // object 1, the small synthetic camera, layers over 650..750 mm
  Capture capture;         // the bracket at one template's pose in front of a wall
  Pose truth;              // that pose
  DetectionResult result;  // with diagnostics; every detection kept (min_confidence 0)
};

// Made once per test binary (a few dozen templates, one frame of the small camera).
const DetectedBracketFrame& BracketFrame();

}  // namespace layermod::test
