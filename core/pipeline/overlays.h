// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pipeline/detector.h"

namespace layermod {

// Images of what each detection stage saw, drawn over the capture's colour image (BGR8). Used by
// `layermod detect --overlay/--overlay-stages` and the studio's preview (which shows the same
// pictures, so the CLI and GUI never disagree).

// Blocks W_j tinted by depth layer, with a legend of layer depths.
cv::Mat DrawRegionDivision(const cv::Mat& color, const ObjectDiagnostics& diagnostics,
                           const ArchiveObject& object);

// Detection points: kept (green) and rejected (red); kept blocks outlined.
cv::Mat DrawCoarsePositioning(const cv::Mat& color, const ObjectDiagnostics& diagnostics);

// Raw template matches: template boxes with their similarity.
cv::Mat DrawMatches(const cv::Mat& color, const ObjectDiagnostics& diagnostics,
                    const TemplateArchive& archive);

// Final poses: projected model contour and axes (x red, y green, z blue), label with score.
cv::Mat DrawPoses(const cv::Mat& color, const std::vector<Detection>& detections,
                  const Detector& detector, const PinholeCamera& camera);

// Colour of depth layer `index` of `count` (BGR), shared with the studio's legend.
cv::Scalar LayerColor(int index, int count);

}  // namespace layermod
