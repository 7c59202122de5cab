// Checks and views of numpy arrays at the module's boundary.

#include "arrays.hpp"

#include <bit>

namespace py = pybind11;

namespace collidescope::python {
namespace {

std::string shape_text(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t d = 0; d < array.ndim(); ++d) text += (d ? ", " : "") + std::to_string(array.shape(d));
    return text + (array.ndim() == 1 ? ",)" : ")");
}

std::string dtype_text(const py::array& array) { return py::str(array.dtype()).cast<std::string>(); }

py::array as_array(const py::handle& value, const std::string& label, const char* what) {
    if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value);
    try {
        return py::module_::import("numpy").attr("asarray")(value).cast<py::array>();
    } catch (const py::error_already_set&) {
        throw py::value_error(label + ": " + what + " is not an array");
    }
}

void check_shape(const py::array& array, const std::string& label, const char* what, const char* expected) {
    if (array.ndim() != 2 || array.shape(1) != 3) {
        throw py::value_error(label + ": " + what + " of shape " + shape_text(array) + ", expected " + expected);
    }
}

}  // namespace

std::string label_of(std::size_t object, const std::string& name) {
    std::string label = "object " + std::to_string(object);
    if (!name.empty()) label += " ('" + name + "')";
    return label;
}

py::array positions_array(const py::handle& positions, const std::string& label) {
    py::array array = as_array(positions, label, "positions");
    const char kind = array.dtype().kind();
    const auto size = array.dtype().itemsize();
    if (kind != 'f' || (size != 4 && size != 8)) {
        throw py::value_error(label + ": positions of dtype " + dtype_text(array) + ", expected float32 or float64");
    }
    check_shape(array, label, "positions", "(V, 3)");
    // The view reads the bytes in place, in this machine's order: an array of the other byte
    // order ('>f8' here) is converted to native order first (numpy's astype: one copy).
    constexpr char k_foreign_order = std::endian::native == std::endian::little ? '>' : '<';
    if (array.dtype().byteorder() == k_foreign_order) {
        array = array.attr("astype")(array.dtype().attr("newbyteorder")("=")).cast<py::array>();
    }
    return array;
}

VertexView positions_view(const py::array& array) {
    const bool single = array.dtype().itemsize() == 4;
    return {array.data(), static_cast<std::size_t>(array.shape(0)), single ? Scalar::Float32 : Scalar::Float64,
            array.strides(0), array.strides(1)};
}

std::vector<std::array<std::uint32_t, 3>> triangles_of(const py::handle& triangles, const std::string& label) {
    const py::array array = as_array(triangles, label, "triangles");
    const char kind = array.dtype().kind();
    if (kind != 'i' && kind != 'u') {
        throw py::value_error(label + ": triangles of dtype " + dtype_text(array) + ", expected integers");
    }
    check_shape(array, label, "triangles", "(T, 3)");
    const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!indices) throw py::value_error(label + ": triangles do not convert to int64");
    const auto view = indices.unchecked<2>();
    std::vector<std::array<std::uint32_t, 3>> result(static_cast<std::size_t>(view.shape(0)));
    for (py::ssize_t t = 0; t < view.shape(0); ++t) {
        for (py::ssize_t corner = 0; corner < 3; ++corner) {
            const std::int64_t index = view(t, corner);
            if (index < 0 || index > std::int64_t{UINT32_MAX}) {
                throw py::value_error(label + ": triangle " + std::to_string(t) + " corner " + std::to_string(corner) +
                                      " is vertex " + std::to_string(index) + ", not in [0, 2^32)");
            }
            result[static_cast<std::size_t>(t)][static_cast<std::size_t>(corner)] = static_cast<std::uint32_t>(index);
        }
    }
    return result;
}

}  // namespace collidescope::python
