// SPDX-License-Identifier: MIT
#include "arrays.h"

#include <string>

namespace py = pybind11;

namespace layermod::python {
namespace {

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) {
    text += (i ? ", " : "") + std::to_string(array.shape(i));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

std::string Describe(const py::array& array) {
  return "shape " + ShapeText(array) + ", dtype " + py::str(array.dtype()).cast<std::string>();
}

void RequireContiguous(const py::array& array, std::string_view what) {
  if (!(array.flags() & py::array::c_style)) {
    throw py::value_error(std::string(what) +
                          ": array is not C-contiguous (a slice or a transpose); pass "
                          "numpy.ascontiguousarray(" +
                          std::string(what) + ")");
  }
}

}  // namespace

cv::Mat ColorView(const py::array& color) {
  if (color.ndim() != 3 || color.shape(2) != 3 ||
      !color.dtype().is(py::dtype::of<std::uint8_t>())) {
    throw py::value_error("color: expected an H x W x 3 uint8 array (BGR), got " + Describe(color));
  }
  RequireContiguous(color, "color");
  return cv::Mat(static_cast<int>(color.shape(0)), static_cast<int>(color.shape(1)), CV_8UC3,
                 const_cast<void*>(color.data()));
}

cv::Mat DepthView(const py::object& depth_object) {
  if (depth_object.is_none()) return {};
  if (!py::isinstance<py::array>(depth_object)) {
    throw py::value_error("depth: expected a numpy array or None");
  }
  const auto depth = depth_object.cast<py::array>();
  const bool u16 = depth.dtype().is(py::dtype::of<std::uint16_t>());
  const bool f32 = depth.dtype().is(py::dtype::of<float>());
  if (depth.ndim() != 2 || !(u16 || f32)) {
    throw py::value_error(
        "depth: expected an H x W uint16 (mm x depth_scale) or float32 (mm) array, got " +
        Describe(depth));
  }
  RequireContiguous(depth, "depth");
  return cv::Mat(static_cast<int>(depth.shape(0)), static_cast<int>(depth.shape(1)),
                 u16 ? CV_16UC1 : CV_32FC1, const_cast<void*>(depth.data()));
}

std::string JsonText(const py::object& value, std::string_view what) {
  if (value.is_none()) return "{}";
  if (!py::isinstance<py::dict>(value)) {
    throw py::type_error(std::string(what) + ": expected a dict");
  }
  try {
    return py::module_::import("json").attr("dumps")(value).cast<std::string>();
  } catch (py::error_already_set& error) {
    throw py::value_error(std::string(what) + ": not JSON-serialisable: " + error.what());
  }
}

py::object FromJsonText(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

}  // namespace layermod::python
