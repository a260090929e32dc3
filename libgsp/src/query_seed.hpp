#pragma once
// A query's first step, shared by full queries (geodesic_solver.cpp) and bounded ones
// (local_query.cpp): the sources (input order, checked at the API boundary:
// validate_sources.hpp) seeded into the faces of the triangulation queried, and the vertex
// sources' exact values. Then query_propagate.hpp, then the gather (query_gather.hpp).
#include "solver_impl.hpp"

#include <gsp/intrinsic/edge_lengths.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace gsp {

template <class Real>
void GeodesicSolver::Impl::seed(const Triangulation& tri, const std::vector<Source>& sources, FaceRecord<Real>* state,
                                std::vector<QueueEntry<Real>>& queue, std::vector<VertexSeed>& vertex_seeds,
                                detail::TargetSet<Real>* goal, std::vector<Index>* seeded) const {
  const std::vector<double>& length = tri.length;
  const double scale = 1.0 / mean_edge;
  // A face-point source as seeded: its face in the layout's order, its weights normalised,
  // and its index in `sources`.
  struct SeededFacePoint {
    Source source;
    Index label;
  };
  std::vector<SeededFacePoint> face_points;   // multi-source runs only (see below)
  // Vertex v (layout order) as a source at distance `value` (model units): its value, and
  // every face of its fan with the virtual source at v, queued over the edge opposite v.
  auto seed_vertex = [&](Index v, double value, Index label) {
    vertex_seeds.push_back({v, value, label});
    if (goal) goal->vertex_value(v, Real(value * scale));
    for (Index k = tri.corner_begin[v]; k < tri.corner_begin[v + 1]; ++k) {
      const Index c = tri.corners[k];
      const Index f = face_of(c);
      if (skipped_face[f]) continue;
      if (seed_face(length, f, kCornerWeights[corner_of(c)], scale, value * scale, label, state)) {
        queue.push_back({next_halfedge(c), state[f].dT});   // the edge opposite v
        if (seeded) seeded->push_back(f);
      }
    }
  };

  for (std::size_t s = 0; s < sources.size(); ++s) {
    const Source& src = sources[s];
    const Index label = static_cast<Index>(s);
    if (src.is_vertex()) {
      seed_vertex(maps.vertex_to_layout(src.element), src.offset, label);
    } else {
      std::array<double, 3> b = src.barycentric;
      // A doubled face's point lies in the copy the propagation kept.
      Index f = intrinsic::kept_copy(mesh().triangles, input.corner_begin, input.corners, skipped_face,
                                     maps.face_to_layout(src.element), b);
      const double sum = b[0] + b[1] + b[2];
      if (skipped_face[f]) continue;   // a face repeating a vertex has no interior
      double w[3] = {b[0] / sum, b[1] / sum, b[2] / sum};
      if (&tri == delaunay.get()) {
        // The input face's point on the flipped faces (flip_replay.hpp). Its input face's
        // corners get their straight in-face distance as their value (exact: the segment is on
        // the surface): the flipped face holding the point need not hold them, and one virtual
        // source per face could bend on the way (a CAD tray's long face: its far corner 18.6%
        // long without). Only as values, not as seeds of their fans (seed_vertex): seeded, the
        // corpus's face points came out no better (malign MRE 0.2157 -> 0.2182%, session 29).
        const Triangle& corners = mesh().triangles[f];
        const Vec3 at = w[0] * mesh().positions[corners[0]] + w[1] * mesh().positions[corners[1]] +
                        w[2] * mesh().positions[corners[2]];
        for (Index v : corners) {
          const double value = src.offset + distance(at, mesh().positions[v]);
          vertex_seeds.push_back({v, value, label});
          if (goal) goal->vertex_value(v, Real(value * scale));
        }
        const auto [face, weights] = flip_replay().locate(f, corners, w, tri.triangles());
        f = face;
        for (int i = 0; i < 3; ++i) w[i] = weights[i];
      }
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
      seed_vertex(v, fp.source.offset + std::hypot(p[i][0] - px, p[i][1] - py), fp.label);   // model units
    }
  }
  // One seed per vertex, by vertex: of several sources at one vertex the smallest value, the
  // first source on ties. Every later step applies this list as it is.
  std::stable_sort(vertex_seeds.begin(), vertex_seeds.end(), [](const VertexSeed& a, const VertexSeed& b) {
    return a.vertex != b.vertex ? a.vertex < b.vertex : a.value < b.value;
  });
  vertex_seeds.erase(std::unique(vertex_seeds.begin(), vertex_seeds.end(),
                                 [](const VertexSeed& a, const VertexSeed& b) { return a.vertex == b.vertex; }),
                     vertex_seeds.end());
}

}  // namespace gsp
