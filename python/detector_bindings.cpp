// SPDX-License-Identifier: MIT
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <layermod/detector.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "arrays.h"
#include "bindings.h"

namespace py = pybind11;

namespace layermod::python {
namespace {

py::array_t<double> RotationArray(const Eigen::Matrix3d& R) {
  py::array_t<double> array({3, 3});
  auto view = array.mutable_unchecked<2>();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) view(r, c) = R(r, c);
  }
  return array;
}

py::array_t<double> VectorArray(const Eigen::Vector3d& t) {
  py::array_t<double> array(3);
  auto view = array.mutable_unchecked<1>();
  for (int i = 0; i < 3; ++i) view(i) = t(i);
  return array;
}

py::dict TimingsDict(const api::Timings& t) {
  py::dict timings;
  timings["prepare_ms"] = t.prepare_ms;
  timings["regions_ms"] = t.regions_ms;
  timings["coarse_ms"] = t.coarse_ms;
  timings["match_ms"] = t.match_ms;
  timings["pose_ms"] = t.pose_ms;
  timings["total_ms"] = t.total_ms;
  return timings;
}

// Archives by path (str or os.PathLike) or as layermod.Archive objects.
std::vector<api::Archive> ArchiveList(const py::iterable& items) {
  if (py::isinstance<py::str>(items)) {
    throw py::type_error("archives: expected a list of paths or layermod.Archive, got one str");
  }
  std::vector<api::Archive> archives;
  for (const py::handle item : items) {
    if (py::isinstance<api::Archive>(item)) {
      archives.push_back(item.cast<api::Archive>());
    } else {
      const auto path = item.cast<std::filesystem::path>();
      py::gil_scoped_release release;
      archives.push_back(api::Archive::Load(path));
    }
  }
  return archives;
}

api::DetectionResult Detect(const api::Detector& detector, const py::array& color,
                            const py::object& depth, const py::object& camera, double depth_scale) {
  api::Capture capture;
  capture.color_bgr = ColorView(color);
  capture.depth = DepthView(depth);
  capture.depth_scale = depth_scale;
  capture.camera = camera.is_none() ? detector.camera() : camera.cast<api::Camera>();
  if (!capture.depth.empty() && capture.depth.size() != capture.color_bgr.size()) {
    throw py::value_error("depth is " + std::to_string(capture.depth.rows) + " x " +
                          std::to_string(capture.depth.cols) + " but color is " +
                          std::to_string(capture.color_bgr.rows) + " x " +
                          std::to_string(capture.color_bgr.cols) + ": they must be the same size");
  }
  if (!(depth_scale > 0.0)) throw py::value_error("depth_scale must be > 0");
  // The arrays stay referenced by the caller's arguments while the GIL is released.
  py::gil_scoped_release release;
  return detector.Detect(capture);
}

void BindDetection(py::module_& m) {
  using api::Detection;
  py::class_<Detection>(m, "Detection",
                        "One detected instance. Pose cam_from_model: x_cam = R @ x_model + t, "
                        "t in mm (BOP's cam_R_m2c / cam_t_m2c).")
      .def_readonly("obj_id", &Detection::obj_id)
      .def_readonly("name", &Detection::name)
      .def_readonly("score", &Detection::score, "LineMOD similarity, percent")
      .def_readonly("ranking", &Detection::ranking,
                    "score x depth fit^2 x colour agreement, percent: the order of detections")
      .def_readonly("confidence", &Detection::confidence,
                    "how likely the pose is right, 0..1 (detections below the detector's "
                    "min_confidence are not reported)")
      .def_property_readonly("R", [](const Detection& d) { return RotationArray(d.R); })
      .def_property_readonly("t", [](const Detection& d) { return VectorArray(d.t_mm); })
      .def_property_readonly(
          "pose",
          [](const Detection& d) {
            py::array_t<double> pose({4, 4});
            auto view = pose.mutable_unchecked<2>();
            for (int r = 0; r < 4; ++r) {
              for (int c = 0; c < 4; ++c) {
                view(r, c) = r == 3 ? (c == 3 ? 1.0 : 0.0) : c == 3 ? d.t_mm(r) : d.R(r, c);
              }
            }
            return pose;
          },
          "4 x 4 cam_from_model, mm")
      .def_readonly("template_id", &Detection::template_id)
      .def_readonly("layer_index", &Detection::layer_index)
      .def_readonly("layer_mm", &Detection::layer_depth_mm)
      .def_property_readonly(
          "box_tl", [](const Detection& d) { return py::make_tuple(d.box_x_px, d.box_y_px); })
      .def_readonly("icp_iterations", &Detection::icp_iterations)
      .def_readonly("icp_rmse_mm", &Detection::icp_rmse_mm)
      .def_readonly("icp_inlier_ratio", &Detection::icp_inlier_ratio)
      .def_readonly("depth_inlier_ratio", &Detection::depth_inlier_ratio)
      .def_readonly("depth_fit", &Detection::depth_fit)
      .def_readonly("visible_ratio", &Detection::visible_ratio)
      .def_readonly("occluded_ratio", &Detection::occluded_ratio)
      .def_readonly("contradicted_ratio", &Detection::contradicted_ratio)
      .def_readonly("surface_continuation", &Detection::surface_continuation)
      .def_readonly("color_agreement", &Detection::color_agreement)
      .def_readonly("outline_agreement", &Detection::outline_agreement)
      .def("__repr__", [](const Detection& d) {
        std::ostringstream text;
        text << "layermod.Detection(obj_id=" << d.obj_id << ", name='" << d.name
             << "', score=" << d.score << ", t=[" << d.t_mm.x() << ", " << d.t_mm.y() << ", "
             << d.t_mm.z() << "])";
        return text.str();
      });
}

void BindResult(py::module_& m) {
  using api::DetectionResult;
  py::class_<DetectionResult>(m, "DetectionResult",
                              "What detect() returns: .detections (best first) and .timings "
                              "(ms per stage); iterating it iterates the detections.")
      .def_readonly("detections", &DetectionResult::detections)
      .def_property_readonly("timings",
                             [](const DetectionResult& r) { return TimingsDict(r.timings); })
      .def_readonly("mode", &DetectionResult::mode)
      .def("__len__", [](const DetectionResult& r) { return r.detections.size(); })
      .def("__getitem__",
           [](const DetectionResult& r, py::ssize_t i) {
             const auto n = static_cast<py::ssize_t>(r.detections.size());
             if (i < 0) i += n;
             if (i < 0 || i >= n) throw py::index_error("detection index out of range");
             return r.detections[static_cast<std::size_t>(i)];
           })
      .def(
          "__iter__",
          [](const DetectionResult& r) {
            return py::make_iterator(r.detections.begin(), r.detections.end());
          },
          py::keep_alive<0, 1>())
      .def(
          "to_json", [](const DetectionResult& r) { return api::ToJson(r); },
          "The result as `layermod detect --json` writes it.");
}

}  // namespace

void BindDetector(py::module_& m) {
  BindDetection(m);
  BindResult(m);
  using api::Detector;
  py::class_<Detector>(
      m, "Detector",
      "Detects the objects of one or more archives, loaded once. detect() releases the GIL; one "
      "Detector may serve several threads at once.")
      .def(py::init([](const py::iterable& archives, const py::object& options) {
             const std::string json = JsonText(options, "options");
             std::vector<api::Archive> list = ArchiveList(archives);
             py::gil_scoped_release release;
             return Detector(std::move(list), json);
           }),
           py::arg("archives"), py::arg("options") = py::none(),
           "archives: paths or layermod.Archive objects. options: a dict of `layermod detect` "
           "settings by name ('-' as '_'), e.g. {'mode': 'scene-patch', 'threshold': 70}.")
      .def("detect", &Detect, py::arg("color"), py::arg("depth") = py::none(),
           py::arg("camera") = py::none(), py::arg("depth_scale") = 1.0,
           "color: H x W x 3 uint8 BGR; depth: H x W uint16 (x depth_scale = mm) or float32 mm, "
           "0 = invalid, or None (mode 'color-only'); camera: defaults to the archives' camera. "
           "Returns a DetectionResult. ValueError for bad arrays, layermod.Error for a capture "
           "the archives cannot use.")
      .def(
          "with_options",
          [](const Detector& detector, const py::object& options) {
            return detector.WithOptions(JsonText(options, "options"));
          },
          py::arg("options"), "The same archives with other options (nothing is rebuilt).")
      .def_property_readonly("camera", &Detector::camera)
      .def_property_readonly("options",
                             [](const Detector& d) { return FromJsonText(d.OptionsJson()); })
      .def_property_readonly("archives", &Detector::archives);
}

}  // namespace layermod::python
