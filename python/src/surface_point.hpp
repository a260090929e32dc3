#pragma once
// gsp.SurfacePoint(face, (b0, b1, b2)), which is the core's gsp::SurfacePoint bound as it is
// (Python makes face points; vertices are plain ints), and the conversion of "sources" / "end
// points" arguments: a vertex index, a SurfacePoint, or a list / 1-D array mixing them.
#include <gsp/geodesics.hpp>

#include <pybind11/pybind11.h>

#include <vector>

namespace gsp::python {

void bind_surface_point(pybind11::module_& m);

// An int or numpy integer (not a bool, not an array).
bool is_index(const pybind11::handle& h);
// One point: an int (vertex) or a SurfacePoint. Throws ValueError naming `what` when it is
// neither or names a missing vertex / face.
Source source_from(const pybind11::handle& h, const TriangleMesh& mesh, const char* what);
// One point or a list / array of them (an empty list is an error).
std::vector<Source> sources_from(const pybind11::handle& h, const TriangleMesh& mesh, const char* what);

}  // namespace gsp::python
