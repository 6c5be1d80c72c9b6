// SPDX-License-Identifier: MIT
#include "ui/common/image_convert.h"

namespace layermod::ui {

QImage ToQImage(const cv::Mat& image) {
  if (image.empty() || image.depth() != CV_8U) return {};
  const int bytes_per_line = static_cast<int>(image.step[0]);
  if (image.channels() == 1) {
    return QImage(image.data, image.cols, image.rows, bytes_per_line, QImage::Format_Grayscale8)
        .copy();
  }
  if (image.channels() != 3) return {};
  return QImage(image.data, image.cols, image.rows, bytes_per_line, QImage::Format_BGR888).copy();
}

}  // namespace layermod::ui
