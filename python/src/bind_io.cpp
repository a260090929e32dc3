// gsp.read_mesh, gsp.write_mesh, gsp.read_points: the apps' readers, writers and welding.
#include "arrays.hpp"
#include "bindings.hpp"

#include <gsp/cli/load.hpp>
#include <gsp/io/colormap.hpp>
#include <gsp/io/mesh_io.hpp>

#include <cmath>

namespace gsp::python {

namespace {

cli::LoadedMesh load(const py::object& path, const py::object& weld, double tolerance, bool require_faces) {
  cli::LoadOptions options;
  if (!weld.is_none()) options.weld = weld.cast<bool>() ? cli::WeldMode::always : cli::WeldMode::never;
  if (!std::isfinite(tolerance) || tolerance < 0) throw py::value_error("weld_tolerance must be a finite number >= 0");
  options.weld_tolerance = tolerance;
  options.require_faces = require_faces;
  const std::string file = path_string(path);
  py::gil_scoped_release nogil;
  return cli::load_mesh(file, options);
}

py::tuple read_mesh(const py::object& path, const py::object& weld, double weld_tolerance) {
  cli::LoadedMesh in = load(path, weld, weld_tolerance, true);
  return py::make_tuple(to_array(std::move(in.mesh.positions)), to_array(in.mesh.triangles));
}

py::object read_points(const py::object& path, bool normals) {
  cli::LoadedMesh in = load(path, py::bool_(false), 0.0, false);
  if (!normals) return to_array(std::move(in.mesh.positions));
  std::vector<Vec3> n = std::move(in.mesh.normals);
  n.resize(in.mesh.num_vertices());   // no normals in the file: zeros
  return py::make_tuple(to_array(std::move(in.mesh.positions)), to_array(std::move(n)));
}

void write_mesh(const py::object& path, const py::handle& V, const py::handle& F, const py::handle& values,
                const py::handle& labels, const std::string& name, const std::string& label_name,
                const py::object& colormap, bool ascii) {
  const std::string file = path_string(path);
  const TriangleMesh mesh = mesh_from_arrays(V, F);
  const std::size_t n = mesh.num_vertices();
  io::VertexAttributes attributes;
  if (!values.is_none()) {
    const std::vector<double> v = values_from(values, n, "values");
    if (io::format_from_path(file) == io::Format::txt) {
      py::gil_scoped_release nogil;
      io::write_values_txt(file, v);
      return;
    }
    std::vector<float> stored(n);
    for (std::size_t i = 0; i < n; ++i) stored[i] = std::isfinite(v[i]) ? float(v[i]) : -1.0f;
    attributes.scalars.push_back({name, stored});
    if (io::format_from_path(file) == io::Format::ply && name != "quality")
      attributes.scalars.push_back({"quality", stored});   // MeshLab colours and filters by quality
    if (!colormap.is_none()) {
      const std::string map = colormap.cast<std::string>();
      if (map != "viridis" && map != "turbo") throw py::value_error("colormap must be 'viridis', 'turbo' or None");
      attributes.colors = io::colorize(v, map == "turbo" ? io::ColorMap::turbo : io::ColorMap::viridis);
    }
  }
  if (!labels.is_none()) {
    const std::vector<double> l = values_from(labels, n, "labels");
    std::vector<std::int32_t> ints(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (l[i] != std::floor(l[i]) || std::abs(l[i]) > 2147483647.0) throw py::value_error("labels must be int32 integers");
      ints[i] = std::int32_t(l[i]);
    }
    attributes.labels.push_back({label_name, ints});
  }
  io::WriteOptions options;
  options.ascii = ascii;
  py::gil_scoped_release nogil;
  io::write_mesh(file, mesh, attributes, options);
}

}  // namespace

std::string path_string(const py::object& path) {
  return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

void bind_io(py::module_& m) {
  m.def("read_mesh", &read_mesh, py::arg("path"), py::arg("weld") = py::none(), py::kw_only(),
        py::arg("weld_tolerance") = 0.0,
        R"(Read a triangle mesh (.obj .ply .off .stl .gltf .glb) as (V, F).

V is float64 (n, 3), F int64 (m, 3); polygons are fan-triangulated. weld=None welds the
formats that split vertices (STL, glTF, GLB) and keeps the others as stored, like the apps;
True welds whatever the format, False never. Welding merges identical positions and positions
within rounding noise (1e-10 of the bounding box's diagonal); weld_tolerance > 0 merges
vertices closer than that instead (model units). Raises OSError for a missing, unreadable or malformed file, and for a
file without faces (use read_points).)");
  m.def("read_points", &read_points, py::arg("path"), py::kw_only(), py::arg("normals") = false,
        R"(Read the vertices of any mesh or point-cloud file (.xyz .txt .ply .obj ...) as P, float64 (n, 3).

normals=True returns (P, N) with the file's normals (zeros where it has none). Raises OSError.)");
  m.def("write_mesh", &write_mesh, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("values") = py::none(),
        py::kw_only(), py::arg("labels") = py::none(), py::arg("name") = "distance", py::arg("label_name") = "label",
        py::arg("colormap") = "viridis", py::arg("ascii") = false,
        R"(Write a mesh (.ply .obj .off .gltf .glb), atomically (never a partial file).

values (n,) float: a per-vertex scalar named `name` (PLY also as `quality` for MeshLab, glTF
as `_NAME`), non-finite values stored as -1, plus vertex colours by `colormap` ('viridis',
'turbo' or None). A .txt path writes only the values, one per line. labels (n,) int: an int
attribute `label_name`. Raises OSError (unwritable, STL/XYZ output) and ValueError (shapes).)");
}

}  // namespace gsp::python
