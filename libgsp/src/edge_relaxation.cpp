#include <gsp/intrinsic/edge_relaxation.hpp>

#include "vertex_relaxation.hpp"

#include <limits>

namespace gsp::intrinsic {

std::vector<Index> relax_along_edges(const TriangleMesh& mesh, const Connectivity& conn,
                                     const std::vector<double>& length, const std::vector<bool>& skipped_face,
                                     std::vector<double>& distance, std::vector<Index>& label, std::size_t& relaxed,
                                     const std::vector<Index>* from) {
  return detail::relax_along_edges<double>(mesh.triangles, length, 1.0, skipped_face, conn.vertex_corner_begin,
                                           conn.vertex_corners, from, std::numeric_limits<double>::infinity(),
                                           kPseudoSourceGain, distance, label, relaxed);
}

}  // namespace gsp::intrinsic
