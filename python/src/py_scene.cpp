// collidescope.scene(spec) / scene_files(inputs): the frames `collidescope check` runs, as
// numpy arrays, to feed a Session in examples, tests and benchmarks.

#include "bindings.hpp"

#include "collidescope/scene_frames.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace collidescope::python {
namespace {

py::list triangles(SceneFrames& scene, std::uint32_t frame) {
    scene.load(frame);
    py::list result;
    for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
        const auto tris = scene.triangles(k);
        py::array_t<std::int64_t> array({static_cast<py::ssize_t>(tris.size()), py::ssize_t{3}});
        auto out = array.mutable_unchecked<2>();
        for (std::size_t t = 0; t < tris.size(); ++t) {
            for (std::size_t c = 0; c < 3; ++c) out(static_cast<py::ssize_t>(t), static_cast<py::ssize_t>(c)) = tris[t][c];
        }
        result.append(std::move(array));
    }
    return result;
}

py::list positions(SceneFrames& scene, std::uint32_t frame) {
    scene.load(frame);
    py::list result;
    for (std::uint32_t k = 0; k < scene.object_count(); ++k) {
        const auto xyz = scene.positions(k);
        py::array_t<double> array({static_cast<py::ssize_t>(xyz.size() / 3), py::ssize_t{3}});
        std::copy(xyz.begin(), xyz.end(), array.mutable_data());
        result.append(std::move(array));
    }
    return result;
}

}  // namespace

void bind_scene(py::module_& m) {
    py::class_<SceneFrames>(m, "Scene", "The frames of a scene `collidescope check` runs, as numpy arrays.")
        .def_property_readonly("name", &SceneFrames::name)
        .def_property_readonly("objects", [](const SceneFrames& s) {
            std::vector<std::string> names;
            for (std::uint32_t k = 0; k < s.object_count(); ++k) names.push_back(s.object_name(k));
            return names;
        }, "Object names, in input order.")
        .def_property_readonly("self_collision", &SceneFrames::self_collision, "The scene's own self-collision setting.")
        .def("__len__", &SceneFrames::frame_count)
        .def("triangles", &triangles, py::arg("frame") = 0, "One (T, 3) int64 array per object, of frame `frame`.")
        .def("positions", &positions, py::arg("frame"), "One (V, 3) float64 array per object (copies).");
    m.def("scene", &SceneFrames::builtin, py::arg("spec"),
          "A built-in scene, NAME[:PRESET] as `check --scene` takes it (C:small, demo, ...).");
    m.def("scene_files", [](const std::vector<std::string>& inputs) { return SceneFrames::open(inputs); },
          py::arg("inputs"), "Mesh files, frame patterns or a scene.json, as `check INPUT...` takes them.");
}

}  // namespace collidescope::python
