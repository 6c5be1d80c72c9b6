// SPDX-License-Identifier: MIT
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <layermod/error.h>
#include <layermod/training.h>

#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>

#include "arrays.h"
#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {
namespace {

api::Camera CameraArgument(const py::object& camera) {
  if (py::isinstance<api::Camera>(camera)) return camera.cast<api::Camera>();
  return api::Camera::FromJson(camera.cast<std::filesystem::path>());
}

// A profile dict becomes JSON; a str / os.PathLike is a profile file; None: the defaults.
void SetProfile(const py::object& profile, api::TrainOptions& options) {
  if (profile.is_none()) return;
  if (py::isinstance<py::dict>(profile)) {
    options.profile_json = JsonText(profile, "profile");
  } else {
    options.profile_file = profile.cast<std::filesystem::path>();
  }
}

api::Archive Train(const py::object& model, std::int32_t obj_id, const std::string& name,
                   const py::object& camera, const py::object& profile, const py::object& out,
                   const std::string& units, int threads, std::size_t max_triangles,
                   const py::object& progress) {
  api::TrainOptions options;
  options.model = model.cast<std::filesystem::path>();
  options.obj_id = obj_id;
  options.name = name;
  options.camera = CameraArgument(camera);
  SetProfile(profile, options);
  if (!out.is_none()) options.out = out.cast<std::filesystem::path>();
  options.units = units;
  options.threads = threads;
  options.max_render_triangles = max_triangles;

  // The callback runs on worker threads: it takes the GIL, and an exception it raises (or
  // Ctrl-C) cancels the training and is raised again here.
  std::atomic<bool> cancel{false};
  std::mutex failure_mutex;
  std::exception_ptr failure;
  api::ProgressCallback report = [&](std::size_t done, std::size_t total, std::string_view stage) {
    if (cancel.load()) return;
    py::gil_scoped_acquire acquire;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none()) progress(done, total, std::string(stage));
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      cancel.store(true);
    }
  };
  try {
    py::gil_scoped_release release;
    return api::Train(options, report, &cancel);
  } catch (const Cancelled&) {
    if (failure) std::rethrow_exception(failure);
    throw;
  }
}

}  // namespace

void BindTraining(py::module_& m) {
  m.def("train", &Train, py::kw_only(), py::arg("model"), py::arg("obj_id") = 1,
        py::arg("name") = "", py::arg("camera"), py::arg("profile") = py::none(),
        py::arg("out") = py::none(), py::arg("units") = "mm", py::arg("threads") = 0,
        py::arg("max_triangles") = 12000, py::arg("progress") = py::none(),
        "Trains multi-scale LineMOD templates of a mesh, as `layermod train` does, and returns "
        "the Archive (also written to `out` when given). camera: a layermod.Camera or a "
        "camera.json path; profile: a dict or a profile file (depth_min_mm, depth_max_mm, views, "
        "features), None for the defaults; progress: called as progress(done, total, stage); "
        "an exception it raises cancels the training and is raised by train().");
}

}  // namespace layermod::python
