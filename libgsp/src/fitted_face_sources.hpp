#pragma once
// GeodesicOptions::fitted_face_sources: after a full run on the intrinsic Delaunay faces, each
// input face's virtual source, chosen among the flipped faces it overlaps (face_frames.hpp) and
// their neighbours across an edge as the one whose distances at the input face's corners come
// closest to the vertices' values, unfolded into the input face's plane and raised where it
// reads below the straight line from its source. Part of the gather (query_gather.hpp). docs/gsp-core.md, "Fitted face sources".
#include "intrinsic_geometry.hpp"
#include "solver_impl.hpp"
#include "virtual_source.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gsp {

namespace detail {

// How much a face's source (at s, sigma behind it, label `source`) is raised so that it reads at
// or above the straight line from its source everywhere on the face (line_shortfall); 0 where
// there is no 3D line to keep (no such source point, or lengths not the 3D ones: line_scale
// other than 1). The fitted sources and a solver without flips (query_gather.hpp) both ask it.
inline double raise_to_line(const Vec3 corners3d[3], const Vec3& s, double sigma, Index source,
                            const std::vector<SourcePoint>& points, double line_scale) {
  if (source >= points.size() || line_scale != 1) return 0.0;
  return line_shortfall(corners3d, s, sigma, points[source].position, points[source].offset);
}

}  // namespace detail

template <class Real>
void GeodesicSolver::Impl::fitted_face_sources(const FaceRecord<Real>* state, GeodesicResult& result,
                                                unsigned threads,
                                                const std::vector<detail::SourcePoint>& points) const {
  const std::size_t nf = mesh().num_faces();
  const detail::FaceFrames& frames_of = face_frames();
  const Triangulation& tri = *delaunay;
  const std::vector<Triangle>& flipped = tri.triangles();
  result.face_sources.assign(nf, VirtualSource{});
  // Of the flipped faces an input face overlaps (face_frames.hpp) and their neighbours across
  // an edge, the source whose distances at the input face's corners come closest to the
  // vertices' values. One flipped face's source need not fit the whole input face: a long CAD
  // face crosses several, some behind a hole or a saddle; and a face's own record may be a
  // saddle's, far off at its other corners.
  // A face whose own source fits its corners within 0.1% of their distances keeps it: the
  // neighbours would move the readings by less than the field's own error (corpus, readings at
  // the corners: benign MRE 0.2080 -> 0.2104% against searching every face, malign unchanged;
  // the search ran on 80% of a benign scan's faces at 1e-5).
  constexpr double kFits = 1e-3;
  // The vertices' values and labels in memory order.
  std::vector<double> vdist(mesh().num_vertices());
  std::vector<Index> vlab(mesh().num_vertices());
  detail::for_ranges(threads, vdist.size(), [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t v = begin; v < end; ++v) {
      vdist[v] = result.vertex_distance[maps.vertex_to_input(Index(v))];
      vlab[v] = result.vertex_source[maps.vertex_to_input(Index(v))];
    }
  });
  // Each face on its own (threads: ranges of faces).
  detail::for_ranges(threads, nf, [&](std::size_t face_begin, std::size_t face_end, unsigned) {
    for (std::size_t fi = face_begin; fi < face_end; ++fi) {
      if (skipped_face[fi]) continue;   // copies: below; faces repeating a vertex: no plane
      const Triangle& t = mesh().triangles[fi];
      const double d[3] = {vdist[t[0]], vdist[t[1]], vdist[t[2]]};
      VirtualSource& vs = result.face_sources[maps.face_to_input(Index(fi))];
      const detail::FaceFrame* first = frames_of.begin(Index(fi));
      const detail::FaceFrame* last = frames_of.end(Index(fi));
      const FaceRecord<Real>& own_record = state[fi];
      const Vec3 corners3d[3] = {mesh().positions[t[0]], mesh().positions[t[1]], mesh().positions[t[2]]};
      // How much longer the path behind a source at s must be for it to read at or above the
      // straight line from its source everywhere on the face (virtual_source.hpp).
      auto shortfall = [&](const Vec3& s, double sigma, Index source) {
        return detail::raise_to_line(corners3d, s, sigma, source, points, line_scale);
      };
      if (first == last && flipped[fi] == t && own_record.reached()) {
        // Most faces: no flip rewrote them and their own source fits their corners (checked in
        // the record's frame, as the propagation reads it).
        double misfit = 0;
        for (Index i = 0; i < 3; ++i)
          if (std::isfinite(d[i])) misfit += std::abs(double(corner_distance(own_record, i)) * mean_edge - d[i]);
        if (misfit <= kFits * (d[0] + d[1] + d[2])) {
          vs.position = detail::canonical_to_3d(mesh(), Index(fi), double(own_record.sx) * mean_edge,
                                                double(own_record.sy) * mean_edge);
          vs.sigma = double(own_record.sigma) * mean_edge;
          vs.source = own_record.source();
          // Raised to the line where it reads below it; searched like the others where that
          // costs more than the fit's tolerance.
          const double raise = shortfall(vs.position, vs.sigma, vs.source);
          if (misfit + 3 * raise <= kFits * (d[0] + d[1] + d[2])) {
            vs.sigma += raise;
            continue;
          }
          vs = VirtualSource{};
        }
      }
      double best_misfit = std::numeric_limits<double>::infinity();
      // The face's label is the propagation's at its centroid (its own record, or the flipped
      // face holding its centroid: the first candidate considered sets it). Only sources of
      // that label compete, so the fit never moves a geodesic Voronoi boundary.
      const bool one_label = vlab[t[0]] == vlab[t[1]] && vlab[t[0]] == vlab[t[2]];
      Index label = kInvalidIndex;
      // A candidate is judged by what it reads at the corners in 3D (a sliver's frame through
      // the flips and its 3D shape agree only up to rounding, which a far source magnifies),
      // after the raise that keeps it at or above the straight line (shortfall).
      auto consider = [&](const FaceRecord<Real>& st, const double at[3][2], double sx, double sy) {
        if (!st.reached()) return;
        if (label == kInvalidIndex) label = st.source();
        Vec3 s;
        if (st.source() != label || !detail::unfolded_to_3d(corners3d, at, sx, sy, s)) return;
        double sigma = double(st.sigma) * mean_edge;
        double reading[3];
        for (int i = 0; i < 3; ++i) reading[i] = sigma + distance(corners3d[i], s);
        // Below the straight line from the source somewhere on the face: the candidate's path
        // length behind its source rises until it reads the line everywhere (a longer path,
        // still one on the surface).
        const double raise = shortfall(s, sigma, label);
        sigma += raise;
        for (double& r : reading) r += raise;
        double misfit = 0;
        for (int i = 0; i < 3; ++i)
          if (std::isfinite(d[i])) misfit += reading[i] - d[i] > 0 ? reading[i] - d[i] : d[i] - reading[i];
        if (!(misfit < best_misfit)) return;
        best_misfit = misfit, vs.position = s, vs.sigma = sigma, vs.source = st.source();
      };
      // A face no flip rewrote is its own flipped face (its corners perhaps in another order).
      detail::FaceFrame own{Index(fi), {}};
      if (first == last) {
        double g[3][2];
        detail::canonical_corners(tri.length, Index(fi), 1.0, g);
        for (int c = 0; c < 3; ++c) {
          const int i = int(std::find(flipped[fi].begin(), flipped[fi].end(), t[c]) - flipped[fi].begin());
          own.at[c][0] = g[i % 3][0], own.at[c][1] = g[i % 3][1];
        }
        first = &own, last = &own + 1;
      }
      for (const detail::FaceFrame* fr = first; fr != last; ++fr) {
        const Index g = fr->face;
        consider(state[g], fr->at, double(state[g].sx) * mean_edge, double(state[g].sy) * mean_edge);
        if (best_misfit <= kFits * (d[0] + d[1] + d[2])) break;   // the face's own source fits
        // A face whose corners are nearest to different sources is cut by their bisector: no one
        // source fits it, and a search would trade one corner's error for another's.
        if (!one_label) continue;
        for (Index i = 0; i < 3; ++i) {
          const Index from = flipped[g][i], to = flipped[g][(i + 1) % 3];
          for (Index h = tri.ring[3 * g + i] & detail::kRingIndexMask; face_of(h) != g;
               h = tri.ring[h] & detail::kRingIndexMask) {
            const Index n = face_of(h), j = corner_of(h);
            const Triangle& tn = flipped[n];
            const bool same_dir = tn[j] == from;
            if (!(same_dir ? tn[(j + 1) % 3] == to : tn[j] == to && tn[(j + 1) % 3] == from)) continue;
            if (!state[n].reached()) continue;
            double s[2];
            detail::across_edge(&tri.length[3 * g], i, &tri.length[3 * n], j, same_dir,
                                double(state[n].sx) * mean_edge, double(state[n].sy) * mean_edge, s);
            consider(state[n], fr->at, s[0], s[1]);
          }
        }
      }
      if (vs.reached() || !std::isfinite(std::min({d[0], d[1], d[2]}))) continue;
      // No candidate (every one reads a corner below its value, or the face has no area): a
      // pseudo-source at its nearest corner with that vertex's distance, a path on the surface.
      const int best = int(std::min_element(d, d + 3) - d);
      vs.position = corners3d[best];
      vs.sigma = d[best];
      vs.source = vlab[t[best]];
    }
  });
  for (const auto& [copy, kept] : face_copies) result.face_sources[copy] = result.face_sources[kept];
}

}  // namespace gsp
