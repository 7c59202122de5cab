#pragma once
// The Python module's input boundary: numpy arrays (or anything numpy.asarray takes) checked
// and viewed as the facade's inputs, with one-line ValueErrors naming the object and element.

#include "collidescope/vertex_view.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace collidescope::python {

/// `positions` as a (V, 3) float32 or float64 array (any strides, not copied; only an array
/// in the other byte order is converted to native order): the array to keep alive and the
/// view into it. Throws ValueError naming `label` on another dtype or shape.
pybind11::array positions_array(const pybind11::handle& positions, const std::string& label);
VertexView positions_view(const pybind11::array& array);

/// `triangles` as (T, 3) integers in [0, 2^32), copied. Throws ValueError naming `label` and
/// the triangle and corner of a negative or too large index, or the dtype or shape.
std::vector<std::array<std::uint32_t, 3>> triangles_of(const pybind11::handle& triangles, const std::string& label);

/// "object 2" or "object 2 ('cloth')", as the facade names objects.
std::string label_of(std::size_t object, const std::string& name);

}  // namespace collidescope::python
