// collidescope._core: the compiled half of the Python package (python/collidescope/ is the
// rest). Errors: bad input (InputError) becomes ValueError, a missing capability
// collidescope.UnavailableError (a RuntimeError), other engine errors RuntimeError, each with
// the engine's one-line message.

#include "bindings.hpp"

#include "collidescope/error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
    m.doc() = "collidescope's compiled core: Session and the scenes of `collidescope check`.";
    static py::exception<collidescope::UnavailableError> unavailable(m, "UnavailableError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const collidescope::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const collidescope::UnavailableError& e) {
            unavailable(e.what());
        }
    });
    collidescope::python::bind_session(m);
    collidescope::python::bind_scene(m);
}
