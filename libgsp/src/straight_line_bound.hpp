#pragma once
// The straight-line bound (internal): no curve on the surface from a source s (3D point,
// offset o) to a point x is shorter than the segment, so a distance below min_s |x - s| + o is
// wrong by construction. After the propagation (and the vertex relaxation) every vertex value
// below that bound is raised to it: the value then errs less than before, whatever the true
// distance (it is at least the bound), and the upper bound still holds (a segment is no longer
// than any path along the edges).
//
// Why a projection and not only a fix of the cause: the propagation's values come from
// unfoldings, and where a face's single virtual source was carried past a vertex on the wrong
// side (CAD fans, needles, saddles of soups; docs/gsp-core.md, "The straight-line bound") the
// unfolded segment is shorter than anything in 3D. Those values are a small fraction of the
// vertices of a few meshes; the bound repairs them wherever they come from, and the count is
// reported (PropagationStats::raised_to_line) so the cause stays measurable.
//
// With SolverOptions::edge_lengths only when edge_lengths_line_scale gives s > 0 (no path
// shorter than s times its 3D length, as in a metric that dominates s^2 I): the positions and
// sources are then scaled by s (GeodesicSolver::Impl::line_bound_positions).
#include "index_maps.hpp"
#include "nearest_source.hpp"
#include "parallel_ranges.hpp"

#include <gsp/geodesics.hpp>

#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace gsp::detail {

// The sources as 3D points. `mesh` is the solver's reordered mesh, `maps` takes input
// indices to it (sources name input vertices and faces; the corner order of a face is kept).
inline std::vector<SourcePoint> source_points(const TriangleMesh& mesh, const IndexMaps& maps,
                                              const std::vector<Source>& sources) {
  std::vector<SourcePoint> out;
  out.reserve(sources.size());
  for (const Source& s : sources) {
    const SurfacePoint in_layout = s.is_vertex() ? SurfacePoint::at_vertex(maps.vertex_to_layout(s.element))
                                                 : SurfacePoint::in_face(maps.face_to_layout(s.element), s.barycentric);
    out.push_back({in_layout.position(mesh), s.offset});
  }
  return out;
}

// The same bound inside the propagation (update_step.hpp, StraightLineTest): the vertices and
// the sources in 3D, in mean edge lengths from the centre of the mesh's bounding box, in single
// precision (4 floats per source: x, y, z, offset); for caller-supplied lengths the positions
// scaled by their line scale first.
inline std::vector<float> scaled_positions(const std::vector<Vec3>& positions, double scale, Vec3 centre) {
  std::vector<float> out(3 * positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec3 p = (positions[i] - centre) * scale;
    out[3 * i] = float(p.x), out[3 * i + 1] = float(p.y), out[3 * i + 2] = float(p.z);
  }
  return out;
}
inline std::vector<float> scaled_sources(const std::vector<SourcePoint>& sources, double scale, Vec3 centre) {
  std::vector<float> out;
  out.reserve(4 * sources.size());
  for (const SourcePoint& s : sources) {
    const Vec3 p = (s.position - centre) * scale;
    out.insert(out.end(), {float(p.x), float(p.y), float(p.z), float(s.offset * scale)});
  }
  return out;
}

// Raises the values below the bound at their vertex to it (and sets the label to the nearest
// source by the bound); unreached (+inf) values are left. Value i belongs to vertex ids[i]
// (ids == nullptr: vertex i) of `positions`. The values are in the propagation's units
// (`scaled`: model units / mean_edge, as the full query keeps them, per vertex) or in model
// units (the bounded query, per layout vertex); either way a raised value is the bound as the
// propagation's precision `Real` holds it, rounded up, so both queries give the same numbers.
// Returns how many were raised by more than 1e-6 of the bound (the rest is rounding of exact
// values). Cost: a squared distance per vertex (to its labelled source, in the order of the
// arrays) and, for the few clearly below it, a search of the sources (nearest_source.hpp); a
// full query runs it on its threads.
template <class Real, class Value>
std::size_t raise_to_straight_line(std::size_t n, const Index* ids, const std::vector<Vec3>& positions, Value* d,
                                   Index* label, double mean_edge, bool scaled,
                                   const std::vector<SourcePoint>& sources, unsigned threads = 1) {
  if (sources.empty()) return 0;
  const NearestSource nearest_source(sources);
  std::atomic<std::size_t> raised{0};
  // Several threads (a full query's): one range of values each.
  for_ranges(threads, n, [&](std::size_t begin, std::size_t end, unsigned) {
    std::size_t raised_here = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const std::size_t i = ids ? ids[k] : k;
      if (!(d[i] < std::numeric_limits<Value>::infinity())) continue;
      const double di = scaled ? double(d[i]) * mean_edge : double(d[i]);
      const Vec3 x = positions[i];
      const Index l = label[i];
      auto raise_to = [&](double bound, Index nearest) {
        Real v = Real(bound / mean_edge);
        if (double(v) * mean_edge < bound) v = std::nextafter(v, std::numeric_limits<Real>::infinity());
        d[i] = scaled ? Value(v) : Value(double(v) * mean_edge);
        label[i] = nearest;
      };
      if (l < sources.size()) {
        const double r = di - sources[l].offset;
        const Vec3 e = x - sources[l].position;
        const double e2 = dot(e, e);
        if (r >= 0 && r * r >= e2) continue;
        // Within rounding (1e-6) of the line to its own source, as a straight geodesic in the
        // propagation's precision often is: raised to that line. The nearest source's bound
        // can lie at most that much lower, and searching every source for it cost a fifth of
        // a query with 1000 sources.
        if (r >= 0 && r * r >= e2 * (1 - 2e-6)) {
          raise_to(std::sqrt(e2) + sources[l].offset, l);
          continue;
        }
      }
      const auto [bound, nearest] = nearest_source(x);
      if (di >= bound) continue;
      raised_here += di < bound * (1 - 1e-6);
      raise_to(bound, nearest);
    }
    raised += raised_here;
  });
  return raised;
}

}  // namespace gsp::detail
