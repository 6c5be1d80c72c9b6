// SPDX-License-Identifier: MIT
#include "scene/depth_mm.h"

#include <cfloat>
#include <cmath>
#include <string>

#include "util/error.h"

namespace layermod {
namespace {

void CheckScale(double mm_per_unit) {
  if (!(mm_per_unit > 0.0) || !std::isfinite(mm_per_unit)) {
    throw Error("depth scale must be a positive number, got " + std::to_string(mm_per_unit));
  }
}

void CheckPixelType(const cv::Mat& depth) {
  if (depth.empty()) throw Error("depth image is empty");
  if (depth.channels() != 1) {
    throw Error("depth image must have 1 channel, got " + std::to_string(depth.channels()));
  }
  if (depth.depth() == CV_8U) {
    throw Error("8-bit depth image; expected 16-bit (scaled to mm) or 32-bit float (mm)");
  }
  if (depth.depth() != CV_16U && depth.depth() != CV_32F) {
    throw Error("depth image must be 16-bit or 32-bit float, got " +
                cv::typeToString(depth.type()));
  }
}

bool AllValid(const cv::Mat& depth_mm) {
  return cv::checkRange(depth_mm, true, nullptr, 0.0, FLT_MAX);
}

void ZeroInvalid(cv::Mat& depth_mm) {
  depth_mm.forEach<float>([](float& value, const int*) {
    if (!(value >= 0.0f && value <= FLT_MAX)) value = 0.0f;  // NaN, infinite, negative
  });
}

}  // namespace

cv::Mat DepthToMillimetres(const cv::Mat& depth, const DepthScale& scale) {
  CheckPixelType(depth);
  const bool is_float = depth.depth() == CV_32F;
  const double mm_per_unit = is_float ? scale.per_float_unit_mm : scale.per_16u_unit_mm;
  CheckScale(mm_per_unit);
  if (is_float && mm_per_unit == 1.0 && AllValid(depth)) return depth;
  cv::Mat depth_mm;
  depth.convertTo(depth_mm, CV_32F, mm_per_unit);
  if (is_float) ZeroInvalid(depth_mm);
  return depth_mm;
}

}  // namespace layermod
