// SPDX-License-Identifier: MIT
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <layermod/archive.h>

#include "arrays.h"
#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {

void BindArchive(py::module_& m) {
  using api::Archive;
  py::class_<Archive>(m, "Archive",
                      "A loaded *.layermod template archive. Immutable; detectors built from it "
                      "share its templates.")
      .def_static("load", &Archive::Load, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
                  "Reads and validates a .layermod file. Raises layermod.IoError / "
                  "layermod.FormatError naming the file.")
      .def("save", &Archive::Save, py::arg("path"), py::call_guard<py::gil_scoped_release>())
      .def_property_readonly("camera", &Archive::camera)
      .def_property_readonly("template_count", &Archive::template_count)
      .def_property_readonly("objects",
                             [](const Archive& archive) {
                               py::list objects;
                               for (const api::ArchiveObjectInfo& o : archive.objects()) {
                                 py::dict entry;
                                 entry["obj_id"] = o.obj_id;
                                 entry["name"] = o.name;
                                 entry["diameter_mm"] = o.diameter_mm;
                                 entry["layer_depths_mm"] = o.layer_depths_mm;
                                 entry["templates"] = o.templates;
                                 objects.append(entry);
                               }
                               return objects;
                             })
      .def(
          "info", [](const Archive& archive) { return FromJsonText(archive.InfoJson(-1)); },
          "What `layermod inspect --json` prints, as a dict.");
  m.def("load_archive", &Archive::Load, py::arg("path"), py::call_guard<py::gil_scoped_release>(),
        "layermod.Archive.load(path).");
}

}  // namespace layermod::python
