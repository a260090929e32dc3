// The compiled part of the Python package gsp (gsp._gsp); python/gsp/__init__.py re-exports it.
#include "bindings.hpp"
#include "errors.hpp"
#include "surface_point.hpp"

PYBIND11_MODULE(_gsp, m) {
  using namespace gsp::python;
  m.doc() = "Geodesic Source Propagation: geodesic distances, paths, sampling and remeshing on meshes and point clouds.";
  register_errors(m);
  bind_surface_point(m);
  bind_io(m);
  bind_metric(m);
  bind_solver(m);
  bind_paths(m);
  bind_lines(m);
  bind_pointcloud(m);
  bind_sampling(m);
  bind_cvt(m);
  bind_windows(m);
#ifdef GSP_VERSION
  m.attr("__version__") = GSP_VERSION;
#endif
}
