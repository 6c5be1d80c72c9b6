// SPDX-License-Identifier: MIT
#include <pybind11/stl/filesystem.h>

#include <layermod/camera.h>

#include <sstream>

#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {

void BindCamera(py::module_& m) {
  using api::Camera;
  py::class_<Camera>(m, "Camera",
                     "Pinhole intrinsics in pixels: a camera-frame point (x, y, z) in mm projects "
                     "to (fx x / z + cx, fy y / z + cy).")
      .def(py::init([](double fx, double fy, double cx, double cy, int width, int height) {
             Camera camera{fx, fy, cx, cy, width, height};
             camera.Validate();
             return camera;
           }),
           py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("width"),
           py::arg("height"), "Raises layermod.Error for non-finite or out-of-range values.")
      .def_static("from_json", &Camera::FromJson, py::arg("path"),
                  "Reads a BOP camera.json (fx fy cx cy width height). Raises layermod.IoError / "
                  "layermod.FormatError naming the file.")
      .def_readonly("fx", &Camera::fx)
      .def_readonly("fy", &Camera::fy)
      .def_readonly("cx", &Camera::cx)
      .def_readonly("cy", &Camera::cy)
      .def_readonly("width", &Camera::width)
      .def_readonly("height", &Camera::height)
      .def("__eq__", [](const Camera& a, const Camera& b) { return a == b; })
      .def("__repr__", [](const Camera& c) {
        std::ostringstream text;
        text << "layermod.Camera(fx=" << c.fx << ", fy=" << c.fy << ", cx=" << c.cx
             << ", cy=" << c.cy << ", width=" << c.width << ", height=" << c.height << ")";
        return text.str();
      });
}

}  // namespace layermod::python
