#include "subdivide.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <CGAL/subdivision_method_3.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace gsp::bench {

TriangleMesh midpoint_subdivide(const TriangleMesh& mesh, int times) {
  TriangleMesh m = mesh;
  for (int round = 0; round < times; ++round) {
    TriangleMesh out;
    out.positions = m.positions;
    out.triangles.reserve(4 * m.triangles.size());
    std::unordered_map<std::uint64_t, Index> midpoint;   // undirected edge -> its new vertex
    midpoint.reserve(3 * m.triangles.size() / 2);
    auto at = [&](Index a, Index b) {
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto [it, added] = midpoint.emplace(key, Index(out.positions.size()));
      if (added) out.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
      return it->second;
    };
    for (const Triangle& t : m.triangles) {
      const Index ab = at(t[0], t[1]), bc = at(t[1], t[2]), ca = at(t[2], t[0]);
      out.triangles.push_back({t[0], ab, ca});
      out.triangles.push_back({ab, t[1], bc});
      out.triangles.push_back({ca, bc, t[2]});
      out.triangles.push_back({ab, bc, ca});
    }
    m = std::move(out);
  }
  return m;
}

TriangleMesh loop_subdivide(const TriangleMesh& mesh, int times) {
  if (times <= 0) return mesh;
  // Only the surface is subdivided: vertices no face uses (scans keep some) are dropped, as
  // CGAL's subdivision walks every vertex's halfedge and an isolated one has none.
  TriangleMesh surface;
  std::vector<Index> slot(mesh.num_vertices(), kInvalidIndex);
  for (const Triangle& t : mesh.triangles)
    for (Index v : t)
      if (slot[v] == kInvalidIndex) slot[v] = Index(surface.positions.size()), surface.positions.push_back(mesh.positions[v]);
  for (const Triangle& t : mesh.triangles) surface.triangles.push_back({slot[t[0]], slot[t[1]], slot[t[2]]});
  if (surface.triangles.empty()) throw InvalidInput("--subdivide: the mesh has no faces");
  adapters::ToCgalResult cgal = adapters::to_cgal(surface);
  if (!cgal.skipped_faces.empty())
    throw InvalidInput("--subdivide: " + std::to_string(cgal.skipped_faces.size()) +
                       " faces are not manifold (Loop subdivision needs a manifold mesh)");
  CGAL::Subdivision_method_3::Loop_subdivision(cgal.mesh, CGAL::parameters::number_of_iterations(times));
  return adapters::from_cgal(cgal.mesh);
}

}  // namespace gsp::bench
