#pragma once
// Every conversion between numpy arrays and the library's types, in one place. Inputs are
// checked here (shape, finiteness, index range) and raise ValueError naming the argument;
// outputs are numpy arrays that take over the library's std::vector without a copy.
#include <gsp/mesh.hpp>
#include <gsp/types.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gsp::python {

namespace py = pybind11;

// V (n,3) float, F (m,3) integer (any numeric dtype that holds integers). Throws ValueError
// for a wrong shape, a non-finite coordinate or an index out of range.
TriangleMesh mesh_from_arrays(const py::handle& V, const py::handle& F);
// (n,3) float positions (a point cloud, or normals); `what` names the argument in errors.
std::vector<Vec3> points_from_array(const py::handle& P, const char* what);
// (n,) or scalar integers in [0, bound); `what` names the argument in errors.
std::vector<Index> indices_from(const py::handle& values, std::size_t bound, const char* what);
// (n,) floats, exactly `count` of them.
std::vector<double> values_from(const py::handle& values, std::size_t count, const char* what);
// A barycentric triple: three finite weights >= 0 summing to 1 within 1e-6.
std::array<double, 3> barycentric_from(const py::handle& b, const char* what);

// The vector's buffer becomes the array's (moved into a capsule that frees it).
py::array_t<double> to_array(std::vector<double>&& values);
// (n,3) float64 viewing the moved vector of Vec3 (three packed doubles each).
py::array_t<double> to_array(std::vector<Vec3>&& points);
// (n,3) float64 from barycentric triples.
py::array_t<double> to_array(std::vector<std::array<double, 3>>&& bary);
// Indices as int64, kInvalidIndex as -1 (numpy has no unsigned sentinel users expect).
py::array_t<std::int64_t> labels_to_array(const std::vector<Index>& labels);
// (m,3) int64 triangles.
py::array_t<std::int64_t> to_array(const std::vector<Triangle>& triangles);

}  // namespace gsp::python
