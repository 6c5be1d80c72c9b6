// SPDX-License-Identifier: MIT
// Feature candidates of one pyramid level of a template view, per modality: the pixels that may
// become features, with the scores SelectScatteredFeatures ranks them by.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "features/feature_selection.h"
#include "features/normal_frame.h"
#include "geometry/camera.h"

namespace layermod {

// Strong colour gradients (magnitude > `strong_magnitude`, label from QuantizeColorGradients with
// `weak_magnitude`) at the non-zero pixels of `region` (CV_8U, the image's size), thinned to the
// ridge of the magnitude across the edge (a pixel is kept when no neighbour along its gradient
// orientation is stronger): the edge's centre line, not a 3-4 px band, so candidates are fewer
// and features sit on the edge. Positions are image pixels + `offset_px`; score = magnitude.
std::vector<FeatureCandidate> ColorGradientCandidates(const cv::Mat& bgr, const cv::Mat& region,
                                                      cv::Point offset_px, float weak_magnitude,
                                                      float strong_magnitude);

// Distance (px) from each pixel to the nearest pixel that is outside `interior` (CV_8U), has no
// label, or has a label different from one of its 4 neighbours in `quantized`. A feature far from
// label borders keeps its label under small pose changes. 3-4 chamfer distance, CV_32F.
cv::Mat LabelBorderDistance(const cv::Mat& quantized, const cv::Mat& interior);

// Quantized depth normals at the non-zero pixels of `interior` (CV_8U, the depth map's size, e.g.
// the object's mask eroded so that scene normals there do not mix object and background), on the
// pixels with even camera coordinates (normal features end up several pixels apart anyway; this
// quarters the work of the selection). Pixel (u, v) is camera pixel `offset_px` + (u, v).
// Score = LabelBorderDistance. Candidates within 2 px of a label border (such as the thin bands of
// in-between labels that the 5x5 normal fit leaves along ridges) are dropped when at least
// `count` others remain: otherwise the scattered selection would fill its last gaps with them.
std::vector<FeatureCandidate> DepthNormalCandidates(const cv::Mat& depth_mm,
                                                    const cv::Mat& interior,
                                                    const PinholeCamera& camera,
                                                    cv::Point offset_px, float max_depth_step_mm,
                                                    NormalFrame frame, int count);

}  // namespace layermod
