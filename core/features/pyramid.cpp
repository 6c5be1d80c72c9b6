// SPDX-License-Identifier: MIT
#include "features/pyramid.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "util/error.h"

namespace layermod {

cv::Mat DownsampleColor(const cv::Mat& image) {
  if (image.empty()) return image.clone();
  cv::Mat down;
  cv::pyrDown(image, down, cv::Size((image.cols + 1) / 2, (image.rows + 1) / 2),
              cv::BORDER_REPLICATE);
  return down;
}

namespace {

template <typename Pixel>
void DecimateRows(const cv::Mat& image, cv::Mat* down) {
  for (int y = 0; y < down->rows; ++y) {
    const auto* in = image.ptr<Pixel>(2 * y);
    auto* out = down->ptr<Pixel>(y);
    for (int x = 0; x < down->cols; ++x) out[x] = in[2 * static_cast<ptrdiff_t>(x)];
  }
}

}  // namespace

cv::Mat DownsampleNearest(const cv::Mat& image) {
  cv::Mat down(cv::Size((image.cols + 1) / 2, (image.rows + 1) / 2), image.type());
  switch (image.elemSize()) {
    case 1:
      DecimateRows<std::uint8_t>(image, &down);
      break;
    case 2:
      DecimateRows<std::uint16_t>(image, &down);
      break;
    case 4:
      DecimateRows<std::uint32_t>(image, &down);
      break;
    case 12:
      DecimateRows<cv::Vec3i>(image, &down);
      break;
    default:
      for (int y = 0; y < down.rows; ++y) {
        for (int x = 0; x < down.cols; ++x) {
          std::copy_n(image.ptr(2 * y, 2 * x), image.elemSize(), down.ptr(y, x));
        }
      }
  }
  return down;
}

PinholeCamera PyramidLevelCamera(const PinholeCamera& camera, int level) {
  if (level < 0 || level > 15) throw Error("PyramidLevelCamera: level must be 0..15");
  PinholeCamera scaled = camera;
  const double factor = 1.0 / static_cast<double>(1 << level);
  scaled.fx *= factor;
  scaled.fy *= factor;
  scaled.cx *= factor;
  scaled.cy *= factor;
  for (int k = 0; k < level; ++k) {
    scaled.width = (scaled.width + 1) / 2;
    scaled.height = (scaled.height + 1) / 2;
  }
  return scaled;
}

}  // namespace layermod
