// collidescope.Session: the facade's Session for a Python loop. step() checks and views the
// caller's arrays (no copy on the Python side; float64 C-contiguous arrays reach the engine
// with no copy at all), releases the GIL while the engine runs, and hands the pairs back as
// one (N, 4) int64 array.

#include "arrays.hpp"
#include "bindings.hpp"

#include "collidescope/session.hpp"

#include <pybind11/stl.h>

#include <chrono>
#include <optional>

namespace py = pybind11;

namespace collidescope::python {
namespace {

// The Python object: the facade's Session plus the object names for messages.
struct PySession {
    Session session;
    std::vector<std::string> names;

    PySession(const py::sequence& triangles, bool self_collision, const std::string& method, int threads,
              const std::optional<std::string>& record, const std::string& policy,
              const std::optional<std::vector<std::string>>& object_names, const std::string& scene, bool regions)
        : session(SessionOptions{.method = method, .policy = policy, .self_collision = self_collision,
                                 .threads = threads, .record = record.value_or(""), .scene = scene,
                                 .regions = regions}) {
        if (object_names && object_names->size() != triangles.size()) {
            throw py::value_error("names: " + std::to_string(object_names->size()) + " names for " +
                                  std::to_string(triangles.size()) + " objects");
        }
        for (std::size_t k = 0; k < triangles.size(); ++k) {
            std::string name = object_names ? (*object_names)[k] : std::string();
            const auto indices = triangles_of(triangles[k], label_of(k, name));
            session.add_object(std::span<const std::array<std::uint32_t, 3>>(indices), name);
            names.push_back(std::move(name));
        }
    }

    // The last step's regions: a list of dicts, the names of Recording.regions plus "curves"
    // ((closed, (N, 3) float64 points) each) and "predecessors".
    py::list regions() const {
        py::list out;
        for (const StepRegion& r : session.regions()) {
            py::dict region;
            region["id"] = r.id;
            region["obj_a"] = r.obj_a;
            region["obj_b"] = r.obj_b;
            region["pairs"] = r.pairs;
            region["triangles_a"] = r.triangles_a;
            region["triangles_b"] = r.triangles_b;
            region["loops"] = r.loops;
            region["curve_length"] = r.curve_length;
            region["coplanar_area"] = r.coplanar_area;
            region["inside_area_a"] = r.inside_area_a;
            region["inside_area_b"] = r.inside_area_b;
            region["depth"] = r.depth;
            region["box_min"] = py::make_tuple(r.box_min[0], r.box_min[1], r.box_min[2]);
            region["box_max"] = py::make_tuple(r.box_max[0], r.box_max[1], r.box_max[2]);
            py::list curves;
            for (const StepCurve& curve : r.curves) {
                py::array_t<double> points({static_cast<py::ssize_t>(curve.points.size()), py::ssize_t{3}});
                auto view = points.mutable_unchecked<2>();
                for (std::size_t p = 0; p < curve.points.size(); ++p) {
                    for (py::ssize_t c = 0; c < 3; ++c) view(static_cast<py::ssize_t>(p), c) = curve.points[p][std::size_t(c)];
                }
                curves.append(py::make_tuple(curve.closed, std::move(points)));
            }
            region["curves"] = std::move(curves);
            region["predecessors"] = py::cast(r.predecessors);
            out.append(std::move(region));
        }
        return out;
    }

    void set_triangles(std::size_t object, const py::handle& triangles) {
        if (object >= names.size()) {
            throw py::value_error("set_triangles: no object " + std::to_string(object) + " (" +
                                  std::to_string(names.size()) + " declared)");
        }
        const auto indices = triangles_of(triangles, label_of(object, names[object]));
        session.set_triangles(static_cast<std::uint32_t>(object), indices);
    }

    py::array_t<std::int64_t> step(const py::sequence& positions) {
        if (positions.size() != names.size()) {
            throw py::value_error("step: positions for " + std::to_string(positions.size()) + " objects, " +
                                  std::to_string(names.size()) + " declared");
        }
        std::vector<py::array> arrays;
        std::vector<VertexView> views;
        arrays.reserve(names.size());
        views.reserve(names.size());
        for (std::size_t k = 0; k < names.size(); ++k) {
            arrays.push_back(positions_array(positions[k], label_of(k, names[k])));
            views.push_back(positions_view(arrays.back()));
        }
        std::span<const CollidingPair> pairs;
        {
            // The arrays stay referenced by `arrays`; another Python thread writing into them
            // meanwhile is the caller's race, as with any C extension that releases the GIL.
            const py::gil_scoped_release release;
            pairs = session.step(views);
        }
        py::array_t<std::int64_t> result({static_cast<py::ssize_t>(pairs.size()), py::ssize_t{4}});
        auto out = result.mutable_unchecked<2>();
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const auto row = static_cast<py::ssize_t>(i);
            out(row, 0) = pairs[i].obj_a;
            out(row, 1) = pairs[i].tri_a;
            out(row, 2) = pairs[i].obj_b;
            out(row, 3) = pairs[i].tri_b;
        }
        return result;
    }

    py::object stats() const {
        if (session.frame_count() == 0) return py::none();
        return py::module_::import("json").attr("loads")(session.stats_json());
    }
};

constexpr const char* k_doc = R"(Collision detection called from your own loop.

Session(triangles, self_collision=False, method="adaptive", threads=0, record=None,
        policy="cost", names=None, scene="session", regions=False)

triangles: one (T_i, 3) integer array per object (vertex indices), declared once.
step(positions): one (V_i, 3) float32 or float64 array per object, any layout; a float64
C-contiguous array is read in place (no copy), others are converted once (stats
counts.positions_copied_bytes says how many bytes);
returns the frame's colliding pairs as an (N, 4) int64 array of (objA, triA, objB, triB) rows,
sorted as `collidescope check --pairs`. The GIL is released while the engine runs.
stats: the last frame's stats as a dict with the names of `check --stats` (None before a step).
record: an .h5 path; the file `collidescope record` writes (replay, inspect, collidescope.open).
regions: find each step's interpenetration regions and follow them (regions(); recorded too).
close() (or leaving a `with` block) finishes the recording.)";

// The benchmark's C++ side (bench/scripts/session_step.py): steps `session` through `frames` (each a
// list of per-object arrays) in a C++ loop, timing each Session::step alone, as a C++ caller
// would run it; the views are made before the clock starts. Returns seconds per frame.
std::vector<double> cpp_step_times(PySession& session, const py::sequence& frames) {
    std::vector<std::vector<py::array>> arrays(frames.size());
    std::vector<std::vector<VertexView>> views(frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const py::sequence positions = frames[f];
        for (std::size_t k = 0; k < positions.size(); ++k) {
            arrays[f].push_back(positions_array(positions[k], label_of(k, {})));
            views[f].push_back(positions_view(arrays[f].back()));
        }
    }
    std::vector<double> seconds;
    const py::gil_scoped_release release;
    for (const std::vector<VertexView>& frame : views) {
        const auto start = std::chrono::steady_clock::now();
        session.session.step(frame);
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return seconds;
}

}  // namespace

void bind_session(py::module_& m) {
    py::class_<PySession>(m, "Session", k_doc)
        .def(py::init<const py::sequence&, bool, const std::string&, int, const std::optional<std::string>&,
                      const std::string&, const std::optional<std::vector<std::string>>&, const std::string&, bool>(),
             py::arg("triangles"), py::arg("self_collision") = false, py::arg("method") = "adaptive",
             py::arg("threads") = 0, py::arg("record") = py::none(), py::arg("policy") = "cost",
             py::arg("names") = py::none(), py::arg("scene") = "session", py::arg("regions") = false)
        .def("set_triangles", &PySession::set_triangles, py::arg("object"), py::arg("triangles"),
             "Replaces an object's triangles (a topology change) from the next step on, whose positions "
             "may then have another vertex count.")
        .def("step", &PySession::step, py::arg("positions"),
             "Runs one frame; returns the (N, 4) int64 array of colliding pairs, sorted.")
        .def_property_readonly("stats", &PySession::stats, "The last frame's stats (check --stats names), or None.")
        .def("regions", &PySession::regions,
             "The last step's interpenetration regions (Session(..., regions=True)), as check --regions reports them: "
             "a list of dicts (id, obj_a, obj_b, pairs, triangles_a, triangles_b, loops, curve_length, coplanar_area, inside_area_a, inside_area_b, depth, "
             "box_min, box_max, curves: [(closed, (N, 3) points)], predecessors); [] without regions.")
        .def_property_readonly("frame", [](const PySession& s) { return s.session.frame_count(); },
                               "Frames stepped so far (the next frame's number).")
        .def_property_readonly("objects", [](const PySession& s) { return s.names.size(); }, "Objects declared.")
        .def_property_readonly("method", [](const PySession& s) { return s.session.options().method; })
        .def("close", [](PySession& s) { s.session.close(); },
             "Finishes the recording (idempotent); step() raises afterwards.")
        .def("__enter__", [](PySession& s) -> PySession& { return s; }, py::return_value_policy::reference)
        .def("__exit__", [](PySession& s, const py::args&) { s.session.close(); });
    m.def("_cpp_step_times", &cpp_step_times, py::arg("session"), py::arg("frames"),
          "Benchmark hook: seconds per Session::step in a C++ loop over `frames` (bench/scripts/session_step.py).");
}

}  // namespace collidescope::python
