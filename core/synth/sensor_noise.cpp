// SPDX-License-Identifier: MIT
#include "synth/sensor_noise.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "synth/random_draws.h"

namespace layermod {
namespace {

constexpr int kDropPatchPx = 2;  // edge dropouts come in patches, not single pixels

// Pixels next to missing depth or to a jump larger than `jump_at_1m_mm` scaled by the depth
// (a pixel's footprint grows with depth, so the same slant gives a jump proportional to it).
cv::Mat DiscontinuityMask(const cv::Mat& depth_mm, double jump_at_1m_mm) {
  cv::Mat mask = cv::Mat::zeros(depth_mm.size(), CV_8U);
  const auto jump_per_mm = static_cast<float>(jump_at_1m_mm / 1000.0);
  const auto jumps = [jump_per_mm](float a, float b) {
    return (a > 0.0f) != (b > 0.0f) || (a > 0.0f && std::abs(a - b) > jump_per_mm * std::min(a, b));
  };
  for (int y = 0; y < depth_mm.rows; ++y) {
    const float* row = depth_mm.ptr<float>(y);
    const float* below = y + 1 < depth_mm.rows ? depth_mm.ptr<float>(y + 1) : nullptr;
    for (int x = 0; x < depth_mm.cols; ++x) {
      if (x + 1 < depth_mm.cols && jumps(row[x], row[x + 1])) {
        mask.at<uchar>(y, x) = mask.at<uchar>(y, x + 1) = 255;
      }
      if (below != nullptr && jumps(row[x], below[x])) {
        mask.at<uchar>(y, x) = mask.at<uchar>(y + 1, x) = 255;
      }
    }
  }
  return mask;
}

// Removes depth in random patches covering about `probability` of a band around the jumps.
void DropAtDiscontinuities(cv::Mat& depth_mm, const SensorNoiseOptions& options,
                           std::mt19937_64& rng, cv::RNG& cv_rng) {
  if (options.edge_band_max_px == 0 || options.edge_drop_probability <= 0.0) return;
  cv::Mat band = DiscontinuityMask(depth_mm, options.edge_jump_mm);
  const int width = UniformInt(rng, 1, options.edge_band_max_px);
  if (width > 1) {
    cv::dilate(band, band, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(width, width)));
  }
  cv::Mat patches((depth_mm.rows + kDropPatchPx - 1) / kDropPatchPx,
                  (depth_mm.cols + kDropPatchPx - 1) / kDropPatchPx, CV_32F);
  cv_rng.fill(patches, cv::RNG::UNIFORM, 0.0, 1.0);
  cv::resize(patches, patches, cv::Size(patches.cols * kDropPatchPx, patches.rows * kDropPatchPx),
             0, 0, cv::INTER_NEAREST);
  const cv::Mat drop = band & (patches(cv::Rect(0, 0, depth_mm.cols, depth_mm.rows)) <
                               options.edge_drop_probability);
  depth_mm.setTo(0.0f, drop);
}

void AddHoles(cv::Mat& depth_mm, const SensorNoiseOptions& options, std::mt19937_64& rng) {
  if (options.holes_max == 0) return;
  const int count = UniformInt(rng, 1, options.holes_max);
  for (int i = 0; i < count; ++i) {
    // One draw per statement (synth/random_draws.h).
    const int centre_y = UniformInt(rng, 0, depth_mm.rows - 1);
    const int centre_x = UniformInt(rng, 0, depth_mm.cols - 1);
    const int axis_y = UniformInt(rng, 1, options.hole_radius_max_px);
    const int axis_x = UniformInt(rng, 1, options.hole_radius_max_px);
    const cv::Point centre(centre_x, centre_y);
    const cv::Size axes(axis_x, axis_y);
    cv::ellipse(depth_mm, centre, axes, UniformInt(rng, 0, 179), 0, 360, cv::Scalar(0.0),
                cv::FILLED);
  }
}

}  // namespace

double AxialNoiseSigmaMm(double depth_mm, const SensorNoiseOptions& options) {
  const double relative = (depth_mm - options.sigma_reference_mm) / 1000.0;
  return options.sigma_base_mm + options.sigma_quadratic_mm * relative * relative;
}

double QuantizeDepthMm(double depth_mm, double focal_px, const SensorNoiseOptions& options) {
  const double scale = focal_px * options.baseline_mm;
  const double disparity =
      std::round(scale / depth_mm * options.disparity_subpixel) / options.disparity_subpixel;
  return disparity > 0.0 ? scale / disparity : 0.0;
}

cv::Mat ApplyDepthSensorModel(const cv::Mat& clean_depth_mm, const PinholeCamera& camera,
                              const SensorNoiseOptions& options, std::mt19937_64& rng) {
  CV_Assert(clean_depth_mm.type() == CV_32F);
  cv::Mat depth = clean_depth_mm.clone();
  if (!options.enabled) return depth;
  cv::RNG cv_rng(rng());
  depth.setTo(0.0f, (depth < options.min_range_mm) | (depth > options.max_range_mm));
  DropAtDiscontinuities(depth, options, rng, cv_rng);
  cv::Mat gauss(depth.size(), CV_32F);
  cv_rng.fill(gauss, cv::RNG::NORMAL, 0.0, 1.0);
  for (int y = 0; y < depth.rows; ++y) {
    float* row = depth.ptr<float>(y);
    const float* noise = gauss.ptr<float>(y);
    for (int x = 0; x < depth.cols; ++x) {
      if (row[x] <= 0.0f) continue;
      const double noisy = row[x] + AxialNoiseSigmaMm(row[x], options) * noise[x];
      row[x] = static_cast<float>(QuantizeDepthMm(noisy, camera.fx, options));
    }
  }
  AddHoles(depth, options, rng);
  return depth;
}

cv::Mat ApplyColorSensorModel(const cv::Mat& color, const SensorNoiseOptions& options,
                              std::mt19937_64& rng) {
  CV_Assert(color.type() == CV_8UC3);
  if (!options.enabled) return color.clone();
  cv::Mat image;
  color.convertTo(image, CV_32FC3);
  if (options.color_blur_sigma_px > 0.0) {
    cv::GaussianBlur(image, image, cv::Size(), options.color_blur_sigma_px);
  }
  cv::Mat noise(image.size(), CV_32FC3);
  cv::RNG cv_rng(rng());
  cv_rng.fill(noise, cv::RNG::NORMAL, 0.0, options.color_noise_sigma);
  image += noise;
  cv::Mat result;
  image.convertTo(result, CV_8UC3);  // rounds and saturates
  return result;
}

}  // namespace layermod
