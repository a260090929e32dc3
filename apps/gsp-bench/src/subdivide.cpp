#include "subdivide.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <CGAL/subdivision_method_3.h>

#include <string>
#include <vector>

namespace gsp::bench {

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
