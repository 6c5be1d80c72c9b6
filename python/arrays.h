// SPDX-License-Identifier: MIT
// numpy arrays as cv::Mat headers over the same memory (no copy), after checking dtype, shape
// and layout; anything else is a ValueError naming the argument and the problem.
#pragma once

#include <pybind11/numpy.h>

#include <opencv2/core/mat.hpp>
#include <string_view>

namespace layermod::python {

// H x W x 3 uint8, C-contiguous: CV_8UC3 (BGR as OpenCV loads it).
cv::Mat ColorView(const pybind11::array& color);

// H x W uint16 (CV_16UC1) or float32 (CV_32FC1), C-contiguous. None gives an empty Mat.
cv::Mat DepthView(const pybind11::object& depth);

// Opens a JSON object or None as text through Python's json module ("{}" for None).
std::string JsonText(const pybind11::object& value, std::string_view what);

// Text JSON as Python objects (dict, list, ...).
pybind11::object FromJsonText(const std::string& text);

}  // namespace layermod::python
