#pragma once
// A query's first step, shared by full queries (geodesic_solver.cpp) and bounded ones
// (local_query.cpp): the sources (input order, checked here) seeded into the faces of the
// triangulation queried, and the vertex sources' exact values. Then query_propagate.hpp, then
// the gather (query_gather.hpp for a full field, local_query.cpp for a bounded one).
#include "solver_impl.hpp"

#include <gsp/errors.hpp>

#include <algorithm>
#include <string>

namespace gsp {

template <class Real>
void GeodesicSolver::Impl::seed(const Triangulation& tri, const std::vector<Source>& sources, FaceRecord<Real>* state,
                                std::vector<QueueEntry<Real>>& queue, std::vector<VertexSeed>& vertex_seeds,
                                detail::TargetSet<Real>* goal, std::vector<Index>* seeded) const {
  const std::vector<double>& length = tri.length;
  const double scale = 1.0 / mean_edge;
  if (sources.size() >= detail::kNoSource) throw InvalidInput("too many sources (at most 2^26 - 1)");
  // A face-point source as seeded: its face in the layout's order, its weights normalised,
  // and its index in `sources`.
  struct SeededFacePoint {
    Source source;
    Index label;
  };
  std::vector<SeededFacePoint> face_points;   // multi-source runs only (see below)

  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Source& src = sources[s];
    const Index label = static_cast<Index>(s);
    if (!std::isfinite(src.offset) || src.offset < 0)
      throw InvalidInput("source " + std::to_string(s) + ": offset must be finite and >= 0");
    if (!src.exists_in(mesh())) throw InvalidInput("source " + src.missing_from(mesh()));
    if (src.is_vertex()) {
      const Index v = maps.vertex_to_layout(src.element);
      // Repeated vertices are resolved where the seeds are applied (the smallest offset, the
      // first source on ties).
      vertex_seeds.push_back({v, src.offset, label});
      if (goal) goal->vertex_value(v, Real(src.offset * scale));
      for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
        const Index c = tri.corners[k];
        const Index f = face_of(c);
        if (skipped_face[f]) continue;
        if (seed_face(length, f, kCornerWeights[corner_of(c)], scale, src.offset * scale, label, state)) {
          queue.push_back({next_halfedge(c), state[f].dT});   // the edge opposite v
          if (seeded) seeded->push_back(f);
        }
      }
    } else {
      const auto& b = src.barycentric;
      if (!are_barycentric(b))
        throw InvalidInput("source " + std::to_string(s) +
                           ": barycentric coordinates must be >= 0 and sum to 1");
      const double sum = b[0] + b[1] + b[2];
      const Index f = maps.face_to_layout(src.element);
      if (skipped_face[f]) continue;   // a face repeating a vertex has no interior
      const double w[3] = {b[0] / sum, b[1] / sum, b[2] / sum};
      if (seed_face(length, f, w, scale, src.offset * scale, label, state)) {
        for (int i = 0; i < 3; ++i) queue.push_back({3 * f + i, state[f].dT});
        if (seeded) seeded->push_back(f);
      }
      if (sources.size() > 1) face_points.push_back({Source::in_face(f, {w[0], w[1], w[2]}, src.offset), label});
    }
  }
  // A face holds one virtual source: of two sources in one face only the one nearer the
  // centroid is kept, and the other would vanish. A source that lost its face goes on from
  // the face's corners instead (each a vertex source with the straight in-face distance as
  // offset): exact at the corners, the geodesic through a corner beyond them.
  for (const SeededFacePoint& fp : face_points) {
    const Index face = fp.source.element;
    const auto& w = fp.source.barycentric;
    if (state[face].source() == fp.label) continue;
    double p[3][2];
    detail::canonical_corners(length, face, 1.0, p);
    const double px = w[0] * p[0][0] + w[1] * p[1][0] + w[2] * p[2][0];
    const double py = w[0] * p[0][1] + w[1] * p[1][1] + w[2] * p[2][1];
    for (Index i = 0; i < 3; ++i) {
      const Index v = tri.triangles()[face][i];
      const double offset = fp.source.offset + std::hypot(p[i][0] - px, p[i][1] - py);   // model units
      vertex_seeds.push_back({v, offset, fp.label});
      if (goal) goal->vertex_value(v, Real(offset * scale));
      for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
        const Index c = tri.corners[k];
        const Index f = face_of(c);
        if (skipped_face[f]) continue;
        if (seed_face(length, f, kCornerWeights[corner_of(c)], scale, offset * scale, fp.label, state)) {
          queue.push_back({next_halfedge(c), state[f].dT});
          if (seeded) seeded->push_back(f);
        }
      }
    }
  }
}

}  // namespace gsp
