#include "subdivide.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <CGAL/subdivision_method_3.h>

#include <string>

namespace gsp::bench {

TriangleMesh loop_subdivide(const TriangleMesh& mesh, int times) {
  if (times <= 0) return mesh;
  adapters::ToCgalResult cgal = adapters::to_cgal(mesh);
  if (!cgal.skipped_faces.empty())
    throw InvalidInput("--subdivide: " + std::to_string(cgal.skipped_faces.size()) +
                       " faces are not manifold (Loop subdivision needs a manifold mesh)");
  CGAL::Subdivision_method_3::Loop_subdivision(cgal.mesh, CGAL::parameters::number_of_iterations(times));
  return adapters::from_cgal(cgal.mesh);
}

}  // namespace gsp::bench
