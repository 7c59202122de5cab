#pragma once
// The parts of the module `collidescope._core`, one file each.

#include <pybind11/pybind11.h>

namespace collidescope::python {

void bind_session(pybind11::module_& m);  ///< Session (py_session.cpp)
void bind_scene(pybind11::module_& m);    ///< scene(): built-in and file scenes (py_scene.cpp)

}  // namespace collidescope::python
