// SPDX-License-Identifier: MIT
#include <layermod/error.h>
#include <layermod/version.h>

#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {

// The C++ exception family as Python exceptions with the same names and hierarchy; the message
// is the C++ one. Later registrations are tried first, so the derived types come last.
void BindErrors(py::module_& m) {
  // Never destroyed: they must outlive the interpreter's last use of the module.
  static auto* error = new py::exception<Error>(m, "Error", PyExc_Exception);
  static auto* io_error = new py::exception<IoError>(m, "IoError", error->ptr());
  static auto* format_error = new py::exception<FormatError>(m, "FormatError", error->ptr());
  static auto* cancelled = new py::exception<Cancelled>(m, "Cancelled", PyExc_Exception);
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const Cancelled& e) {
      (*cancelled)(e.what());
    } catch (const FormatError& e) {
      (*format_error)(e.what());
    } catch (const IoError& e) {
      (*io_error)(e.what());
    } catch (const Error& e) {
      (*error)(e.what());
    }
  });
}

}  // namespace layermod::python

PYBIND11_MODULE(layermod, m) {
  m.doc() =
      "LayerMOD: multi-scale LineMOD templates and Scene-Patch detection of texture-less parts "
      "with 6D pose in RGB-D images. Load archives once, detect in every frame.";
  m.attr("__version__") = layermod::api::Version();
  m.attr("ARCHIVE_FORMAT_VERSION") = layermod::api::ArchiveFormatVersion();
  layermod::python::BindErrors(m);
  layermod::python::BindCamera(m);
  layermod::python::BindCapture(m);
  layermod::python::BindArchive(m);
  layermod::python::BindDetector(m);
  layermod::python::BindTraining(m);
}
