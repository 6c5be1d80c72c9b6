// SPDX-License-Identifier: MIT
#pragma once

#include <QImage>
#include <opencv2/core.hpp>

namespace layermod::ui {

// Deep copy of a CV_8UC3 (BGR) or CV_8UC1 image; a null QImage for anything else.
QImage ToQImage(const cv::Mat& image);

}  // namespace layermod::ui
