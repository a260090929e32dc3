#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/errors.hpp>
#include <gsp/sampling/random.hpp>
#include <gsp/sampling/surface_points.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gsp::cvt {

namespace {

constexpr double kPi = 3.14159265358979323846;

double angle_at(Vec3 p, Vec3 q, Vec3 r) {   // angle at p in degrees
  const Vec3 u = q - p, v = r - p;
  return std::atan2(norm(cross(u, v)), dot(u, v)) * 180.0 / kPi;
}

}  // namespace

MeshQuality measure_mesh_quality(const TriangleMesh& mesh) {
  MeshQuality q;
  q.triangles = mesh.num_faces();
  q.min_angle = 180;
  std::size_t angles = 0, below = 0, good = 0;
  double sum_min = 0, sum_ar = 0;
  const double tiny = 1e-24 * std::pow(bounding_box(mesh).diagonal(), 4);
  for (const Triangle& t : mesh.triangles) {
    const Vec3 a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    const double area2 = norm(cross(b - a, c - a));
    if (repeats_vertex(t) || !(area2 * area2 > tiny)) {
      q.degenerate++;
      continue;
    }
    const double angs[3] = {angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)};
    const double mn = std::min({angs[0], angs[1], angs[2]});
    for (double x : angs) {
      ++angles;
      below += x < 30.0;
      q.max_angle = std::max(q.max_angle, x);
    }
    q.min_angle = std::min(q.min_angle, mn);
    sum_min += mn;
    const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b);
    const double ar = std::max({la, lb, lc}) * (la + lb + lc) / (4.0 * std::sqrt(3.0) * 0.5 * area2);
    sum_ar += ar;
    q.max_aspect_ratio = std::max(q.max_aspect_ratio, ar);
    ++good;
  }
  if (good) {
    q.mean_min_angle = sum_min / double(good);
    q.mean_aspect_ratio = sum_ar / double(good);
    q.below_30 = double(below) / double(angles);
  } else {
    q.min_angle = 0;
  }
  const Connectivity conn = build_connectivity(mesh);
  std::vector<std::size_t> valence(mesh.num_vertices(), 0);
  double length = 0;
  for (Index e = 0; e < conn.num_edges(); ++e) {
    const Index h = conn.edge_halfedge[e];
    ++valence[from_vertex(mesh, h)];
    ++valence[to_vertex(mesh, h)];
    length += distance(mesh.positions[from_vertex(mesh, h)], mesh.positions[to_vertex(mesh, h)]);
  }
  q.mean_edge_length = conn.num_edges() ? length / double(conn.num_edges()) : 0.0;
  for (std::size_t k : valence) {
    if (k == 0) continue;
    ++q.vertices;
    if (q.valence_histogram.size() <= k) q.valence_histogram.resize(k + 1, 0);
    ++q.valence_histogram[k];
  }
  return q;
}

namespace {

// Max and sum of distances from points of `from` (its vertices and area-uniform samples) to `to`.
void one_side(const TriangleMesh& from, const ClosestPointIndex& to, const HausdorffOptions& o, double& max_d,
              double& sum_d, std::size_t& count) {
  std::vector<bool> used(from.num_vertices(), false);
  for (const Triangle& t : from.triangles)
    for (Index v : t) used[v] = true;
  for (Index v = 0; v < from.num_vertices(); ++v) {
    if (!used[v]) continue;
    const double d = to.closest(from.positions[v]).distance;
    max_d = std::max(max_d, d);
    sum_d += d;
    ++count;
  }
  const sampling::AreaSampler sampler(from);
  sampling::Random random(o.seed);
  for (std::size_t i = 0; i < o.samples; ++i) {
    const double d = to.closest(sampler.draw(from, random).position).distance;
    max_d = std::max(max_d, d);
    sum_d += d;
    ++count;
  }
}

}  // namespace

HausdorffDistance hausdorff_distance(const TriangleMesh& a, const TriangleMesh& b, const HausdorffOptions& o) {
  const ClosestPointIndex ia(a), ib(b);
  HausdorffDistance h;
  double sum = 0;
  std::size_t count = 0;
  one_side(a, ib, o, h.a_to_b, sum, count);
  one_side(b, ia, o, h.b_to_a, sum, count);
  h.two_sided = std::max(h.a_to_b, h.b_to_a);
  h.mean = count ? sum / double(count) : 0.0;
  h.diagonal = bounding_box(a).diagonal();
  h.relative = h.diagonal > 0 ? h.two_sided / h.diagonal : 0.0;
  return h;
}

}  // namespace gsp::cvt
