#include <gsp/connectivity.hpp>
#include <gsp/cvt/features.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::cvt {

namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 face_normal(const TriangleMesh& m, Index f) {
  const Triangle& t = m.triangles[f];
  return cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
}

// Angle in degrees between the two directions (0 when parallel).
double angle_between(Vec3 a, Vec3 b) {
  const double la = norm(a), lb = norm(b);
  if (!(la > 0 && lb > 0)) return 0;
  return std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0)) * 180.0 / kPi;
}

}  // namespace

Features detect_features(const TriangleMesh& mesh, const FeatureOptions& o) {
  const Connectivity conn = build_connectivity(mesh);
  Features out;
  const std::size_t nv = mesh.num_vertices();
  std::vector<std::vector<Index>> adjacent(nv);   // feature edges per vertex (other ends)
  for (Index e = 0; e < conn.num_edges(); ++e) {
    const Index h = conn.edge_halfedge[e];
    const std::size_t ring = conn.ring_size(h);
    bool feature = false;
    if (ring == 1) {
      feature = o.boundary;
    } else if (ring > 2) {
      feature = true;
    } else {
      // Normals of a consistently oriented pair; a pair that runs the same way has one flipped.
      const Index g = conn.radial_next[h];
      Vec3 nf = face_normal(mesh, face_of(h)), ng = face_normal(mesh, face_of(g));
      if (from_vertex(mesh, h) == from_vertex(mesh, g)) ng = -1.0 * ng;
      feature = norm(nf) > 0 && norm(ng) > 0 && angle_between(nf, ng) > o.angle;
    }
    if (!feature) continue;
    Index a = from_vertex(mesh, h), b = to_vertex(mesh, h);
    if (a > b) std::swap(a, b);
    out.edges.push_back({a, b});
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::sort(out.edges.begin(), out.edges.end());

  std::vector<bool> corner(nv, false);
  for (Index v = 0; v < nv; ++v) {
    const std::size_t k = adjacent[v].size();
    if (k == 0) continue;
    if (k != 2) {
      corner[v] = true;
    } else {
      const Vec3 p = mesh.positions[v];
      corner[v] = angle_between(p - mesh.positions[adjacent[v][0]], mesh.positions[adjacent[v][1]] - p) > o.corner_turn;
    }
    if (corner[v]) out.corners.push_back(v);
  }

  // Chains: from every corner along each of its feature edges to the next corner; then the
  // closed curves that have no corner.
  std::vector<std::vector<bool>> used(nv);
  for (Index v = 0; v < nv; ++v) used[v].assign(adjacent[v].size(), false);
  auto mark = [&](Index a, Index b) {
    for (std::size_t i = 0; i < adjacent[a].size(); ++i)
      if (adjacent[a][i] == b && !used[a][i]) {
        used[a][i] = true;
        break;
      }
    for (std::size_t i = 0; i < adjacent[b].size(); ++i)
      if (adjacent[b][i] == a && !used[b][i]) {
        used[b][i] = true;
        break;
      }
  };
  auto walk = [&](Index start, std::size_t first) {
    std::vector<Index> chain{start};
    Index cur = adjacent[start][first];
    mark(start, cur);
    chain.push_back(cur);
    while (!corner[cur] && cur != start) {
      Index next = kInvalidIndex;
      for (std::size_t i = 0; i < adjacent[cur].size(); ++i)
        if (!used[cur][i]) next = adjacent[cur][i];
      if (next == kInvalidIndex) break;
      mark(cur, next);
      cur = next;
      chain.push_back(cur);
    }
    out.curves.push_back(std::move(chain));
  };
  for (Index v : out.corners)
    for (std::size_t i = 0; i < adjacent[v].size(); ++i)
      if (!used[v][i]) walk(v, i);
  for (Index v = 0; v < nv; ++v)
    for (std::size_t i = 0; i < adjacent[v].size(); ++i)
      if (!used[v][i]) walk(v, i);
  return out;
}

}  // namespace gsp::cvt
