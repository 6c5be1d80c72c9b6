// SPDX-License-Identifier: MIT
// LineMOD's per-pixel quantization stages (Hinterstoisser et al., PAMI 2012, §2.4 and §2.6).
// Used on template views and, unchanged, on whole scene images by the detector: every function
// works on any image size (including empty and 1 x 1 images).
//
// Encoding of every quantized image: CV_8U, a pixel is either 0 (no reliable label) or exactly one
// bit `1 << label` with label 0..7. The matcher's spreading and response maps rely on this.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "features/depth_normals.h"  // ComputeDepthNormals, the input of QuantizeNormals

namespace layermod {

// A pixel keeps its gradient label only when at least this many of the 9 pixels of its 3x3
// neighbourhood (itself included) have the same raw label (LineMOD's rule).
inline constexpr int kGradientMinVotes = 5;

// Normals tilted less than this from the optical axis all get kFrontalNormalLabel (see
// QuantizeNormals).
inline constexpr float kDefaultFrontalTiltDeg = 10.0f;
inline constexpr int kFrontalNormalLabel = 0;

// Label 0..7 of a quantized pixel (a single bit), -1 for 0 or for a value with several bits.
inline int LabelOfBit(std::uint8_t bit) {
  if (bit == 0 || (bit & (bit - 1)) != 0) return -1;
  int label = 0;
  while ((bit >>= 1) != 0) ++label;
  return label;
}

// Centre of a gradient label's bin: orientation in degrees over 0..180 (image x right, y down).
inline float GradientLabelAngleDeg(int label) { return static_cast<float>(label) * 22.5f; }
// Gradient label 0..7 of the gradient (dx, dy), sign ignored: the bins of
// QuantizeColorGradients (label k covers 22.5 k +- 11.25 deg). (0, 0) has no orientation; callers
// exclude it.
int GradientOrientationLabel(float dx, float dy);
// Direction of (nx, ny) that a normal label stands for, in degrees over 0..360 (image axes).
inline float NormalLabelAngleDeg(int label) { return static_cast<float>(label) * 45.0f; }

// Colour-gradient orientations. A 7x7 Gaussian blur, then 3x3 Sobel (unnormalised, as LineMOD:
// a step of c grey levels gives a magnitude of about 2 c) on each channel; the channel with the
// largest magnitude gives the pixel's gradient. Its orientation, sign ignored, falls into one of 8
// bins of 22.5 deg over 0..180 deg, centred on the label's angle: label k covers 22.5 k +- 11.25
// deg (OpenCV starts its bins at 0 deg instead, which splits axis-aligned edges, common on
// rendered boxes, between labels 0 and 7 by sub-degree noise). Pixels with magnitude <=
// `weak_magnitude` have no label and do not vote; a labelled pixel keeps its label only when at
// least kGradientMinVotes pixels of its 3x3 neighbourhood (itself included, pixels outside the
// image do not vote) share it, which removes isolated noise.
// `bgr` must be CV_8UC3. `magnitude_out` (optional) receives the CV_32F magnitude.
cv::Mat QuantizeColorGradients(const cv::Mat& bgr, float weak_magnitude,
                               cv::Mat* magnitude_out = nullptr);

// Quantized normals (CV_8U, `1 << label`, 0 where the normal is 0 or not finite). LineMOD assigns
// a normal to the nearest of 8 reference directions on a cone around the optical axis; the
// nearest one is decided by the direction of (nx, ny) alone, so label k stands for (nx, ny)
// pointing at 45 k deg (bins centred there, image axes). A normal facing the camera is equally
// near to all 8 references: normals tilted less than `frontal_tilt_deg` from the optical axis all
// get kFrontalNormalLabel, so that the noisy (nx, ny) direction of flat frontal surfaces does not
// scatter them over random labels (LineMOD's look-up table also gives its central cell one label).
cv::Mat QuantizeNormals(const cv::Mat& normals, float frontal_tilt_deg = kDefaultFrontalTiltDeg);

}  // namespace layermod
