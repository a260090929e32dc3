#include "arrays.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <utility>

namespace gsp::python {

namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] void bad(const std::string& message) { throw py::value_error(message); }

std::string shape_of(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

py::array as_array(const py::handle& h, const char* what) {
  if (h.is_none()) bad(std::string(what) + " is None");
  py::module_ np = py::module_::import("numpy");
  return np.attr("asarray")(h);
}

DoubleArray as_doubles(const py::handle& h, const char* what) {
  py::array a = as_array(h, what);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    bad(std::string(what) + " must hold numbers (got dtype " + std::string(py::str(a.dtype())) + ")");
  return DoubleArray::ensure(a);
}

// An integer array as int64 (any integer dtype; float arrays are refused: an index that is
// 2.5 is a bug upstream, not something to round).
py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> as_integers(const py::handle& h, const char* what) {
  py::array a = as_array(h, what);
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(kind == 'f' && a.size() == 0))
    bad(std::string(what) + " must hold integers (got dtype " + std::string(py::str(a.dtype())) + ")");
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
}

template <class T>
py::capsule owner(T* p) {
  return py::capsule(p, [](void* q) { delete static_cast<T*>(q); });
}

}  // namespace

std::vector<Vec3> points_from_array(const py::handle& P, const char* what) {
  DoubleArray a = as_doubles(P, what);
  if (a.ndim() != 2 || a.shape(1) != 3) bad(std::string(what) + " must have shape (n, 3), got " + shape_of(a));
  std::vector<Vec3> out(std::size_t(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    if (!is_finite(out[i])) bad(std::string(what) + "[" + std::to_string(i) + "] is not finite");
  }
  return out;
}

TriangleMesh mesh_from_arrays(const py::handle& V, const py::handle& F) {
  TriangleMesh mesh;
  mesh.positions = points_from_array(V, "V");
  auto f = as_integers(F, "F");
  if (f.size() == 0 && f.ndim() <= 2) return mesh;   // no faces: a point cloud
  if (f.ndim() != 2 || f.shape(1) != 3) bad("F must have shape (m, 3), got " + shape_of(f));
  const std::int64_t n = std::int64_t(mesh.positions.size());
  mesh.triangles.resize(std::size_t(f.shape(0)));
  const std::int64_t* p = f.data();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t v = p[3 * t + k];
      if (v < 0 || v >= n)
        bad("F[" + std::to_string(t) + "] names vertex " + std::to_string(v) + ", but V has " + std::to_string(n) +
            " vertices");
      mesh.triangles[t][k] = Index(v);
    }
  return mesh;
}

std::vector<Index> indices_from(const py::handle& values, std::size_t bound, const char* what) {
  auto a = as_integers(values, what);
  if (a.ndim() > 1) bad(std::string(what) + " must be an index or a 1-D list of indices, got shape " + shape_of(a));
  std::vector<Index> out(std::size_t(a.size()));
  const std::int64_t* p = a.data();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (p[i] < 0 || std::uint64_t(p[i]) >= bound)
      bad(std::string(what) + ": index " + std::to_string(p[i]) + " out of range [0, " + std::to_string(bound) + ")");
    out[i] = Index(p[i]);
  }
  return out;
}

std::vector<double> values_from(const py::handle& values, std::size_t count, const char* what) {
  DoubleArray a = as_doubles(values, what);
  if (a.ndim() != 1 || std::size_t(a.shape(0)) != count)
    bad(std::string(what) + " must have shape (" + std::to_string(count) + ",), got " + shape_of(a));
  return {a.data(), a.data() + count};
}

std::array<double, 3> barycentric_from(const py::handle& b, const char* what) {
  DoubleArray a = as_doubles(b, what);
  if (a.ndim() != 1 || a.shape(0) != 3) bad(std::string(what) + " must be three weights, got shape " + shape_of(a));
  const std::array<double, 3> w{a.data()[0], a.data()[1], a.data()[2]};
  for (double x : w)
    if (!std::isfinite(x) || x < 0) bad(std::string(what) + ": weights must be finite and >= 0");
  if (std::abs(w[0] + w[1] + w[2] - 1) > 1e-6) bad(std::string(what) + ": weights must sum to 1");
  return w;
}

py::array_t<double> to_array(std::vector<double>&& values) {
  auto* v = new std::vector<double>(std::move(values));
  return py::array_t<double>({py::ssize_t(v->size())}, {py::ssize_t(sizeof(double))}, v->data(), owner(v));
}

py::array_t<double> to_array(std::vector<Vec3>&& points) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  auto* v = new std::vector<Vec3>(std::move(points));
  const auto n = py::ssize_t(v->size());
  return py::array_t<double>({n, py::ssize_t(3)}, {py::ssize_t(sizeof(Vec3)), py::ssize_t(sizeof(double))},
                             reinterpret_cast<const double*>(v->data()), owner(v));
}

py::array_t<double> to_array(std::vector<std::array<double, 3>>&& bary) {
  static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double), "packed triples");
  auto* v = new std::vector<std::array<double, 3>>(std::move(bary));
  const auto n = py::ssize_t(v->size());
  return py::array_t<double>({n, py::ssize_t(3)}, {py::ssize_t(3 * sizeof(double)), py::ssize_t(sizeof(double))},
                             reinterpret_cast<const double*>(v->data()), owner(v));
}

py::array_t<std::int64_t> labels_to_array(const std::vector<Index>& labels) {
  py::array_t<std::int64_t> out(py::ssize_t(labels.size()));
  std::int64_t* p = out.mutable_data();
  for (std::size_t i = 0; i < labels.size(); ++i) p[i] = labels[i] == kInvalidIndex ? -1 : std::int64_t(labels[i]);
  return out;
}

py::array_t<std::int64_t> to_array(const std::vector<Triangle>& triangles) {
  py::array_t<std::int64_t> out({py::ssize_t(triangles.size()), py::ssize_t(3)});
  std::int64_t* p = out.mutable_data();
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) p[3 * t + k] = triangles[t][k];
  return out;
}

}  // namespace gsp::python
