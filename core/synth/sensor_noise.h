// SPDX-License-Identifier: MIT
#pragma once

// A Kinect-like sensor model applied to noiseless renders.

#include <opencv2/core.hpp>
#include <random>

#include "geometry/camera.h"
#include "synth/synth_options.h"

namespace layermod {

// Standard deviation of the axial noise at depth z (mm).
double AxialNoiseSigmaMm(double depth_mm, const SensorNoiseOptions& options);

// Depth after quantising the disparity f * baseline / z to 1/subpixel pixel steps.
double QuantizeDepthMm(double depth_mm, double focal_px, const SensorNoiseOptions& options);

// Sensor depth from a noiseless depth map (CV_32F mm, 0 = nothing): out-of-range depth removed,
// depth lost in patches of a 1..edge_band_max_px band around discontinuities, axial Gaussian
// noise, disparity quantisation, a few small holes. Deterministic for a given `rng` state.
cv::Mat ApplyDepthSensorModel(const cv::Mat& clean_depth_mm, const PinholeCamera& camera,
                              const SensorNoiseOptions& options, std::mt19937_64& rng);

// Sensor colour from a rendered BGR8 image: slight blur, then Gaussian noise.
cv::Mat ApplyColorSensorModel(const cv::Mat& color, const SensorNoiseOptions& options,
                              std::mt19937_64& rng);

}  // namespace layermod
