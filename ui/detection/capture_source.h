// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <vector>

#include "dataset/bop.h"
#include "pipeline/detector.h"

namespace layermod::ui {

// Where a detection preview's RGB-D frame comes from: a BOP frame (split folder, scene, image)
// or a colour image with an optional 16-bit depth PNG and a BOP camera.json.
struct CaptureSource {
  QString bop_dir;  // non-empty: a BOP frame
  int scene_id = 0;
  int frame_id = 0;
  QString color;
  QString depth;  // may be empty: colour-only detection
  QString camera;

  bool is_bop() const { return !bop_dir.isEmpty(); }
  // For titles and error boxes: "scene 1, frame 0 of “/data/test”" or the colour file.
  QString Describe() const;
};

struct LoadedCapture {
  Capture capture;
  std::vector<int> scene_frame_ids;          // a BOP frame's scene: its image ids, ascending
  std::vector<BopGroundTruth> ground_truth;  // a BOP frame's, when the dataset has it
};

// Reads the frame (runs on the worker thread). Throws the core's IoError/FormatError naming the
// file, or Error for a scene or frame the dataset does not have.
LoadedCapture LoadCaptureSource(const CaptureSource& source);

// The frame after (`step` > 0) or before (`step` < 0) `frame_id` among `frame_ids` (ascending);
// -1 when there is none.
int NeighbourFrame(const std::vector<int>& frame_ids, int frame_id, int step);

}  // namespace layermod::ui
