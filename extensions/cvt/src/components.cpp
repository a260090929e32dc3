#include <gsp/connectivity.hpp>
#include <gsp/weld.hpp>
#include <gsp/cvt/components.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

namespace gsp::cvt {

namespace {

Index find_root(std::vector<Index>& parent, Index v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

double triangle_area(const TriangleMesh& m, const Triangle& t) {
  return 0.5 * norm(cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
}

struct Signature {
  std::int64_t euler;
  std::size_t loops;
  bool operator<(const Signature& o) const { return euler != o.euler ? euler < o.euler : loops < o.loops; }
  bool operator==(const Signature& o) const { return euler == o.euler && loops == o.loops; }
};

std::vector<Signature> signatures(const ComponentSplit& s) {
  std::vector<Signature> out;
  for (const TriangleMesh& c : s.meshes) {
    const TopologyReport r = analyze_topology(c, build_connectivity(c));
    out.push_back({r.euler_characteristic, r.boundary_loops});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

ComponentSplit split_components(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  std::vector<Index> parent(nv);
  std::iota(parent.begin(), parent.end(), Index(0));
  for (const Triangle& t : mesh.triangles)
    for (int k = 1; k < 3; ++k) {
      const Index a = find_root(parent, t[0]), b = find_root(parent, t[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  ComponentSplit s;
  s.face_component.assign(nf, kInvalidIndex);
  std::vector<Index> root_component(nv, kInvalidIndex), local(nv, kInvalidIndex);
  for (std::size_t f = 0; f < nf; ++f) {
    const Triangle& t = mesh.triangles[f];
    const Index root = find_root(parent, t[0]);
    if (root_component[root] == kInvalidIndex) {
      root_component[root] = Index(s.meshes.size());
      s.meshes.emplace_back();
      s.vertex_ids.emplace_back();
      s.face_ids.emplace_back();
    }
    const Index c = root_component[root];
    s.face_component[f] = c;
    TriangleMesh& m = s.meshes[c];
    Triangle lt;
    for (int k = 0; k < 3; ++k) {
      if (local[t[k]] == kInvalidIndex) {
        local[t[k]] = Index(m.positions.size());
        m.positions.push_back(mesh.positions[t[k]]);
        if (!mesh.normals.empty()) m.normals.push_back(mesh.normals[t[k]]);
        s.vertex_ids[c].push_back(t[k]);
      }
      lt[k] = local[t[k]];
    }
    m.triangles.push_back(lt);
    s.face_ids[c].push_back(Index(f));
  }
  return s;
}

std::int64_t orient_consistently(TriangleMesh& mesh) {
  const Connectivity conn = build_connectivity(mesh);
  const std::size_t nf = mesh.num_faces();
  std::vector<signed char> flip(nf, -1);   // -1 unvisited, 0 kept, 1 flipped
  std::vector<Index> stack;
  for (std::size_t seed = 0; seed < nf; ++seed) {
    if (flip[seed] >= 0) continue;
    flip[seed] = 0;
    stack.push_back(Index(seed));
    while (!stack.empty()) {
      const Index f = stack.back();
      stack.pop_back();
      for (Index i = 0; i < 3; ++i) {
        const Index h = 3 * f + i;
        if (conn.halfedge_edge[h] == kInvalidIndex || conn.ring_size(h) != 2) continue;
        const Index o = conn.radial_next[h], g = face_of(o);
        // Opposite directions when consistent; the same direction asks for a relative flip.
        const bool same_direction = from_vertex(mesh, h) == from_vertex(mesh, o);
        const auto want = static_cast<signed char>(flip[f] ^ (same_direction ? 1 : 0));
        if (flip[g] < 0) {
          flip[g] = want;
          stack.push_back(g);
        } else if (flip[g] != want) {
          return -1;
        }
      }
    }
  }
  std::int64_t flipped = 0;
  for (std::size_t f = 0; f < nf; ++f)
    if (flip[f] == 1) {
      std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
      ++flipped;
    }
  return flipped;
}

ComponentTopology component_topology(const TriangleMesh& component) {
  ComponentTopology c;
  c.report = analyze_topology(component, build_connectivity(component));
  for (const Triangle& t : component.triangles) c.area += triangle_area(component, t);
  TriangleMesh copy = component;
  c.orientable = orient_consistently(copy) >= 0;
  return c;
}

VertexStitch stitch_boundary_vertices(const TriangleMesh& mesh) {
  const Connectivity conn = build_connectivity(mesh);
  const std::size_t nv = mesh.num_vertices();
  std::vector<bool> on_boundary(nv, false);
  for (Index h = 0; h < conn.num_halfedges(); ++h)
    if (conn.halfedge_edge[h] != kInvalidIndex && conn.radial_next[h] == h)
      on_boundary[from_vertex(mesh, h)] = on_boundary[to_vertex(mesh, h)] = true;
  // The boundary vertices alone, welded by exact position; each then takes its group's first.
  TriangleMesh boundary;
  std::vector<Index> boundary_ids;
  for (Index v = 0; v < nv; ++v)
    if (on_boundary[v]) boundary.positions.push_back(mesh.positions[v]), boundary_ids.push_back(v);
  const WeldResult w = weld_vertices(boundary);
  std::vector<Index> rep(nv);
  std::iota(rep.begin(), rep.end(), Index(0));
  std::vector<Index> first(w.mesh.num_vertices(), kInvalidIndex);
  for (std::size_t i = 0; i < boundary_ids.size(); ++i) {
    Index& f = first[w.vertex_map[i]];
    if (f == kInvalidIndex) f = boundary_ids[i];
    rep[boundary_ids[i]] = f;
  }
  VertexStitch out;
  out.vertex_map.resize(nv);
  for (Index v = 0; v < nv; ++v) {
    if (rep[v] != v) {
      out.vertex_map[v] = out.vertex_map[rep[v]];   // rep[v] < v: numbered already
      ++out.stitched;
      continue;
    }
    out.vertex_map[v] = Index(out.mesh.positions.size());
    out.mesh.positions.push_back(mesh.positions[v]);
  }
  out.mesh.triangles.reserve(mesh.num_faces());
  for (const Triangle& t : mesh.triangles)
    out.mesh.triangles.push_back({out.vertex_map[t[0]], out.vertex_map[t[1]], out.vertex_map[t[2]]});
  return out;
}

TriangleMesh described_surface(const TriangleMesh& mesh) {
  return split_nonmanifold_vertices(drop_duplicate_faces(stitch_boundary_vertices(mesh).mesh).mesh).mesh;
}

FaceCleanup drop_duplicate_faces(const TriangleMesh& mesh) {
  FaceCleanup out;
  out.mesh.positions = mesh.positions;
  const std::vector<bool> duplicate = duplicate_faces(mesh);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (repeats_vertex(t)) {
      ++out.repeated_vertex_faces;
    } else if (duplicate[f]) {
      ++out.duplicate_faces;
    } else {
      out.mesh.triangles.push_back(t);
      out.face_source.push_back(Index(f));
    }
  }
  return out;
}

VertexSplit split_nonmanifold_vertices(const TriangleMesh& mesh) {
  const Connectivity conn = build_connectivity(mesh);
  const std::size_t nf = mesh.num_faces(), nv = mesh.num_vertices();
  auto corner = [&](Index f, Index v) {
    const Triangle& t = mesh.triangles[f];
    return 3 * f + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  // Corners around a vertex are in one fan when their faces share a manifold edge there.
  std::vector<Index> parent(3 * nf);
  std::iota(parent.begin(), parent.end(), Index(0));
  std::vector<bool> on_nonmanifold_edge(nv, false);
  for (Index h = 0; h < conn.num_halfedges(); ++h) {
    if (conn.halfedge_edge[h] == kInvalidIndex) continue;
    const std::size_t ring = conn.ring_size(h);
    const Index a = from_vertex(mesh, h), b = to_vertex(mesh, h);
    if (ring > 2) on_nonmanifold_edge[a] = on_nonmanifold_edge[b] = true;
    if (ring != 2) continue;
    const Index f = face_of(h), g = face_of(conn.radial_next[h]);
    for (Index v : {a, b}) {
      const Index x = find_root(parent, corner(f, v)), y = find_root(parent, corner(g, v));
      if (x != y) parent[std::max(x, y)] = std::min(x, y);
    }
  }
  VertexSplit out;
  out.mesh = mesh;
  out.vertex_source.resize(nv);
  std::iota(out.vertex_source.begin(), out.vertex_source.end(), Index(0));
  // Per vertex, the fan (corner root) that keeps the vertex; other fans get copies.
  std::vector<Index> keeper(nv, kInvalidIndex);
  std::vector<bool> counted(nv, false);
  std::unordered_map<Index, Index> copy_of_root;
  for (Index c = 0; c < 3 * nf; ++c) {
    const Triangle& t = mesh.triangles[c / 3];
    if (repeats_vertex(t)) continue;   // a degenerate face stays as it is
    const Index v = t[c % 3];
    if (on_nonmanifold_edge[v]) continue;
    const Index root = find_root(parent, c);
    if (keeper[v] == kInvalidIndex) keeper[v] = root;
    if (root == keeper[v]) continue;
    auto [it, inserted] = copy_of_root.try_emplace(root, Index(out.mesh.positions.size()));
    if (inserted) {
      out.mesh.positions.push_back(mesh.positions[v]);
      if (!mesh.normals.empty()) out.mesh.normals.push_back(mesh.normals[v]);
      out.vertex_source.push_back(v);
      if (!counted[v]) counted[v] = true, ++out.split;
    }
    out.mesh.triangles[c / 3][c % 3] = it->second;
  }
  return out;
}

std::size_t duplicate_vertices(const TriangleMesh& mesh) {
  std::vector<bool> used(mesh.num_vertices(), false);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) used[v] = true;
  struct Hash {
    std::size_t operator()(const Vec3& p) const {
      std::size_t h = 0;
      for (double x : {p.x, p.y, p.z}) h = h * 1000003u ^ std::hash<double>()(x + 0.0);   // -0 and +0 hash alike
      return h;
    }
  };
  struct Equal {
    bool operator()(const Vec3& a, const Vec3& b) const { return a.x == b.x && a.y == b.y && a.z == b.z; }
  };
  std::unordered_map<Vec3, int, Hash, Equal> seen;
  std::size_t duplicates = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
    if (used[v] && ++seen[mesh.positions[v]] > 1) ++duplicates;
  return duplicates;
}

bool same_topology_per_component(const TriangleMesh& input, const TriangleMesh& output, std::string* why,
                                 std::size_t* defects) {
  auto fail = [&](std::string text, std::size_t places = 0) {
    if (why) *why = std::move(text);
    if (defects) *defects = places;
    return false;
  };
  if (defects) *defects = 0;
  const TopologyReport out = analyze_topology(output, build_connectivity(output));
  if (!out.is_manifold())
    return fail(std::to_string(out.nonmanifold_edges) + " non-manifold edges, " +
                    std::to_string(out.nonmanifold_vertices) + " non-manifold vertices",
                out.nonmanifold_edges + out.nonmanifold_vertices);
  if (out.inconsistent_edges)
    return fail(std::to_string(out.inconsistent_edges) + " inconsistently oriented edges", out.inconsistent_edges);
  if (const std::size_t d = duplicate_vertices(output)) return fail(std::to_string(d) + " duplicate vertices", d);
  const std::vector<Signature> a = signatures(split_components(input)), b = signatures(split_components(output));
  if (a.size() != b.size())
    return fail(std::to_string(b.size()) + " components instead of " + std::to_string(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i]))
      return fail("a component with Euler characteristic " + std::to_string(b[i].euler) + " and " +
                  std::to_string(b[i].loops) + " boundary loops where the input has " + std::to_string(a[i].euler) +
                  " and " + std::to_string(a[i].loops));
  return true;
}

}  // namespace gsp::cvt
