// SPDX-License-Identifier: MIT
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pipeline/detector.h"

namespace layermod {

// Pictures of what each detection stage saw, drawn onto a caller's canvas: the capture's colour
// image (BGR8), usually dimmed first with DimColor so the marks stand out. Drawing adds to what
// is on the canvas, so the stages stack in pipeline order on one image. Used by `layermod detect
// --overlay/--overlay-stages` and the studio's preview (overlay_stack.h), so the CLI and the GUI
// never disagree.

// Darkens `canvas` in place (x 0.6): the background of the stage pictures.
void DimColor(cv::Mat& canvas);

// Blocks W_j tinted by depth layer and outlined in white.
void DrawRegionDivision(cv::Mat& canvas, const ObjectDiagnostics& diagnostics,
                        const ArchiveObject& object);

// The layer colours with their depths, one 18 px line per layer below `top_px`; returns the
// first row below the legend.
int DrawLayerLegend(cv::Mat& canvas, const ArchiveObject& object, int top_px = 0);

// Detection points: kept (green) and rejected (red); kept blocks outlined in yellow.
void DrawCoarsePositioning(cv::Mat& canvas, const ObjectDiagnostics& diagnostics);

// The line explaining the coarse-positioning colours, below `top_px`; returns the first row
// below it.
int DrawCoarseLegend(cv::Mat& canvas, int top_px = 0);

// Raw template matches, best first (at most 10): template boxes with their similarity; the best
// one green with its features, the others orange.
void DrawMatches(cv::Mat& canvas, const ObjectDiagnostics& diagnostics,
                 const TemplateArchive& archive);

// Final poses: projected model contour and axes (x red, y green, z blue), label with score and
// confidence right of and above the projected sphere centre.
void DrawPoses(cv::Mat& canvas, const std::vector<Detection>& detections, const Detector& detector,
               const PinholeCamera& camera);

// Colour of depth layer `index` of `count` (BGR), shared with the studio's legend.
cv::Scalar LayerColor(int index, int count);

}  // namespace layermod
