// SPDX-License-Identifier: MIT
#include <pybind11/numpy.h>
#include <pybind11/stl/filesystem.h>

#include <layermod/capture.h>

#include <filesystem>

#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {
namespace {

// A numpy array over the Mat's pixels; the capsule keeps the Mat (and its buffer) alive.
py::object ArrayOf(const cv::Mat& image) {
  if (image.empty()) return py::none();
  auto* owner = new cv::Mat(image.isContinuous() ? image : image.clone());
  py::capsule keep(owner, [](void* mat) { delete static_cast<cv::Mat*>(mat); });
  std::vector<py::ssize_t> shape = {owner->rows, owner->cols};
  if (owner->channels() > 1) shape.push_back(owner->channels());
  const py::dtype dtype = owner->depth() == CV_8U    ? py::dtype::of<std::uint8_t>()
                          : owner->depth() == CV_16U ? py::dtype::of<std::uint16_t>()
                                                     : py::dtype::of<float>();
  return py::array(dtype, shape, owner->data, keep);
}

}  // namespace

void BindCapture(py::module_& m) {
  m.def(
      "load_capture",
      [](const std::filesystem::path& color, const py::object& depth,
         const std::filesystem::path& camera, double depth_scale) {
        const std::filesystem::path depth_path =
            depth.is_none() ? std::filesystem::path() : depth.cast<std::filesystem::path>();
        api::Capture capture;
        {
          py::gil_scoped_release release;
          capture = api::LoadCapture(color, depth_path, camera, depth_scale);
        }
        return py::make_tuple(ArrayOf(capture.color_bgr), ArrayOf(capture.depth), capture.camera);
      },
      py::arg("color"), py::arg("depth"), py::arg("camera"), py::arg("depth_scale") = 1.0,
      "Reads a frame as `layermod detect` does: (color H x W x 3 uint8 BGR, depth H x W float32 "
      "mm or None, Camera). depth: a 16-bit PNG (value x depth_scale = mm) or None. Raises "
      "layermod.IoError / layermod.FormatError naming the file.");
}

}  // namespace layermod::python
