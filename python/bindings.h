// SPDX-License-Identifier: MIT
// The module's parts, one per topic; module.cpp calls them in order.
#pragma once

#include <pybind11/pybind11.h>

namespace layermod::python {

void BindErrors(pybind11::module_& m);
void BindCamera(pybind11::module_& m);
void BindCapture(pybind11::module_& m);
void BindArchive(pybind11::module_& m);
void BindDetector(pybind11::module_& m);
void BindTraining(pybind11::module_& m);

}  // namespace layermod::python
