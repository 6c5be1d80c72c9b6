// SPDX-License-Identifier: MIT
#include "ui/detection/capture_source.h"

#include <QObject>
#include <algorithm>
#include <iterator>

#include "dataset/bop.h"
#include "pipeline/capture_io.h"
#include "util/error.h"

namespace layermod::ui {
namespace {

BopScene FindScene(const std::string& split_dir, int scene_id) {
  for (BopScene& scene : ListBopScenes(split_dir)) {
    if (scene.scene_id == scene_id) return std::move(scene);
  }
  throw Error("'" + split_dir + "': there is no scene " + std::to_string(scene_id));
}

}  // namespace

QString CaptureSource::Describe() const {
  if (is_bop()) {
    return QObject::tr("scene %1, frame %2 of “%3”").arg(scene_id).arg(frame_id).arg(bop_dir);
  }
  return QStringLiteral("“%1”").arg(color);
}

LoadedCapture LoadCaptureSource(const CaptureSource& source) {
  if (source.is_bop()) {
    const BopScene scene = FindScene(source.bop_dir.toStdString(), source.scene_id);
    BopFrame frame = LoadBopFrame(scene, source.frame_id);
    return {Capture{std::move(frame.color), std::move(frame.depth_mm), frame.camera},
            scene.image_ids, std::move(frame.gt)};
  }
  CaptureFiles files;
  files.color = source.color.toStdString();
  files.depth = source.depth.toStdString();
  files.camera = source.camera.toStdString();
  return {LoadCapture(files), {}, {}};
}

int NeighbourFrame(const std::vector<int>& frame_ids, int frame_id, int step) {
  if (step > 0) {
    const auto next = std::upper_bound(frame_ids.begin(), frame_ids.end(), frame_id);
    return next == frame_ids.end() ? -1 : *next;
  }
  const auto first_not_below = std::lower_bound(frame_ids.begin(), frame_ids.end(), frame_id);
  return first_not_below == frame_ids.begin() ? -1 : *std::prev(first_not_below);
}

}  // namespace layermod::ui
