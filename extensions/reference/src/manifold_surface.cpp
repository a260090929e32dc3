#include "manifold_surface.hpp"

#include <gsp/errors.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

namespace gsp::reference::detail {

namespace {

std::string face_name(std::size_t f) { return "face " + std::to_string(f); }

void check_faces_not_degenerate(const TriangleMesh& mesh) {
  const BoundingBox box = bounding_box(mesh);
  const Vec3 diag = box.max - box.min;
  const double min_area = 1e-12 * dot(diag, diag);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (repeats_vertex(t))
      throw TopologyError(face_name(f) + " names vertex " +
                          std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) +
                          " twice (degenerate face); exact geodesics need a mesh without "
                          "degenerate faces");
    const Vec3& a = mesh.positions[t[0]];
    const double area = 0.5 * norm(cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a));
    if (!(area > min_area))
      throw TopologyError(face_name(f) + " has zero area (degenerate face); exact geodesics "
                          "need a mesh without degenerate faces");
  }
}

struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index(0)); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Halfedge h = 3f + i runs from corner i to corner i+1. Returns, per halfedge, the other
// halfedge on its edge (kInvalidIndex on the boundary); throws on an edge with > 2 faces.
std::vector<Index> pair_halfedges(const TriangleMesh& mesh) {
  const std::size_t nh = 3 * mesh.num_faces();
  std::vector<std::pair<std::uint64_t, Index>> keyed(nh);
  for (std::size_t h = 0; h < nh; ++h) {
    const Triangle& t = mesh.triangles[h / 3];
    const Index a = t[h % 3], b = t[(h + 1) % 3];
    keyed[h] = {(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b), static_cast<Index>(h)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<Index> opposite(nh, kInvalidIndex);
  for (std::size_t i = 0; i < nh;) {
    std::size_t j = i;
    while (j < nh && keyed[j].first == keyed[i].first) ++j;
    if (j - i > 2) {
      const Index a = Index(keyed[i].first >> 32), b = Index(keyed[i].first & 0xffffffffu);
      throw TopologyError("edge " + std::to_string(a) + "-" + std::to_string(b) + " has " +
                          std::to_string(j - i) + " faces (non-manifold edge, first at " +
                          face_name(keyed[i].second / 3) +
                          "); exact geodesics need a manifold mesh");
    }
    if (j - i == 2) {
      opposite[keyed[i].second] = keyed[i + 1].second;
      opposite[keyed[i + 1].second] = keyed[i].second;
    }
    i = j;
  }
  return opposite;
}

Index corner_at(const Triangle& t, Index v) { return t[0] == v ? 0 : (t[1] == v ? 1 : 2); }

// Corners around one vertex that are joined through shared edges form a fan; a manifold
// vertex has exactly one.
void check_vertex_fans(const TriangleMesh& mesh, const std::vector<Index>& opposite) {
  UnionFind corners(3 * mesh.num_faces());
  for (std::size_t h = 0; h < opposite.size(); ++h) {
    const Index o = opposite[h];
    if (o == kInvalidIndex || o < h) continue;
    const Triangle& t = mesh.triangles[h / 3];
    const Triangle& u = mesh.triangles[o / 3];
    for (Index v : {t[h % 3], t[(h + 1) % 3]})
      corners.unite(Index(3 * (h / 3) + corner_at(t, v)), Index(3 * (o / 3) + corner_at(u, v)));
  }
  std::vector<Index> fans(mesh.num_vertices(), 0);
  for (std::size_t c = 0; c < 3 * mesh.num_faces(); ++c) {
    if (corners.find(Index(c)) != c) continue;
    const Index v = mesh.triangles[c / 3][c % 3];
    if (++fans[v] > 1)
      throw TopologyError("vertex " + std::to_string(v) +
                          " joins faces that share no edge around it (non-manifold vertex, at " +
                          face_name(c / 3) + "); exact geodesics need a manifold mesh");
  }
}

// Breadth-first over shared edges: labels components and decides which faces to turn so that
// the two halfedges of every edge run in opposite directions.
void orient_and_label(const TriangleMesh& mesh, const std::vector<Index>& opposite,
                      std::vector<Index>& component, std::vector<char>& flip,
                      std::size_t& num_components) {
  const std::size_t nf = mesh.num_faces();
  component.assign(nf, kInvalidIndex);
  flip.assign(nf, 0);
  num_components = 0;
  std::vector<Index> queue;
  for (std::size_t seed = 0; seed < nf; ++seed) {
    if (component[seed] != kInvalidIndex) continue;
    const Index label = static_cast<Index>(num_components++);
    component[seed] = label;
    queue.assign(1, static_cast<Index>(seed));
    while (!queue.empty()) {
      const Index f = queue.back();
      queue.pop_back();
      for (Index i = 0; i < 3; ++i) {
        const Index h = 3 * f + i, o = opposite[h];
        if (o == kInvalidIndex) continue;
        const Index g = o / 3;
        // Same direction on the shared edge: exactly one of the two faces must turn.
        const bool same_direction = mesh.triangles[f][i] == mesh.triangles[g][o % 3];
        const char want = static_cast<char>(flip[f] ^ (same_direction ? 1 : 0));
        if (component[g] == kInvalidIndex) {
          component[g] = label;
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          throw TopologyError("the component containing " + face_name(f) +
                              " cannot be oriented consistently (non-orientable surface); "
                              "exact geodesics need an orientable mesh");
        }
      }
    }
  }
}

}  // namespace

ManifoldSurface make_manifold_surface(const TriangleMesh& mesh) {
  validate(mesh);
  if (mesh.triangles.empty()) throw TopologyError("mesh has no faces (exact geodesics need a surface)");
  check_faces_not_degenerate(mesh);
  const std::vector<Index> opposite = pair_halfedges(mesh);
  check_vertex_fans(mesh, opposite);

  ManifoldSurface out;
  out.num_input_vertices = mesh.num_vertices();
  out.num_input_faces = mesh.num_faces();
  std::vector<char> flip;
  std::size_t num_components = 0;
  orient_and_label(mesh, opposite, out.face_component, flip, num_components);
  out.components.resize(num_components);

  out.vertex_component.assign(mesh.num_vertices(), kInvalidIndex);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.triangles[f]) out.vertex_component[v] = out.face_component[f];
  out.vertex_local.assign(mesh.num_vertices(), kInvalidIndex);
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const Index c = out.vertex_component[v];
    if (c == kInvalidIndex) {
      ++out.isolated_vertices;
      continue;
    }
    SurfaceComponent& comp = out.components[c];
    out.vertex_local[v] = static_cast<Index>(comp.vertices.size());
    comp.vertices.push_back(static_cast<Index>(v));
    comp.mesh.positions.push_back(mesh.positions[v]);
  }
  out.face_local.assign(mesh.num_faces(), kInvalidIndex);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    SurfaceComponent& comp = out.components[out.face_component[f]];
    const Triangle& t = mesh.triangles[f];
    Triangle local{out.vertex_local[t[0]], out.vertex_local[t[1]], out.vertex_local[t[2]]};
    if (flip[f]) {
      std::swap(local[1], local[2]);
      ++out.flipped_faces;
    }
    out.face_local[f] = static_cast<Index>(comp.faces.size());
    comp.faces.push_back(static_cast<Index>(f));
    comp.mesh.triangles.push_back(local);
  }
  return out;
}

}  // namespace gsp::reference::detail
