#pragma once
// gsp.metric: Riemannian metrics (gsp::anisotropic::MetricField) from Python.
#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/geodesics.hpp>

#include <pybind11/pybind11.h>

namespace gsp::python {

// None: the 3D lengths. A gsp.metric.Metric, a (3,3) tensor (constant) or (k,3,3) / (k,6)
// tensors (per face when k = faces, per vertex when k = vertices; ambiguous counts are an
// error): SolverOptions with the metric's edge lengths. Raises ValueError.
SolverOptions metric_solver_options(const TriangleMesh& mesh, const pybind11::handle& metric);

}  // namespace gsp::python
