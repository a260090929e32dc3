#pragma once
// A full query's last step (after query_seed.hpp and query_propagate.hpp): the per-vertex
// values from the faces' virtual sources, then the dense result in the input's order (vertex
// distances and labels with the vertex sources on top, per-face values and virtual sources
// when asked for). A bounded query's gather, sparse over what it reached, is here too
// (gather_reached, gather_local).
#include "fitted_face_sources.hpp"
#include "solver_impl.hpp"
#include "source_edges.hpp"
#include "virtual_source.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace gsp {

template <class Real>
std::size_t GeodesicSolver::Impl::vertex_minima(const Triangulation& tri, const FaceRecord<Real>* state,
                                                std::vector<Real>& vmin, std::vector<Index>& vlabel,
                                                unsigned threads) const {
  // Per-vertex: the smallest sigma + |corner - virtual source| over the incident reached faces,
  // taken in the propagation's precision (the conversion to model units is monotonic, so the
  // minimum and its label are those of the converted values); at a saddle, of the faces that
  // see their source (corner_values.hpp), the others' only where none does: a value's tier is
  // 0 when seen and reached, else 1, and the smallest (tier, value) wins. Per block of faces
  // two passes: the corner distances, branch-free so the compiler vectorises them (an
  // unreached face has sigma = +inf and gives +inf), then the minima, also without branches:
  // which face wins a vertex is a coin toss the branch predictor loses.
  const std::size_t nf = mesh().num_faces(), nv = mesh().num_vertices();
  const Real inf = std::numeric_limits<Real>::infinity();
  auto scatter = [&](std::size_t first, std::size_t last, std::vector<Real>& dmin, std::vector<Index>& label_of,
                     std::vector<std::uint8_t>& tier) {
    dmin.assign(nv, inf);
    label_of.assign(nv, kInvalidIndex);
    tier.assign(nv, 1);
    std::size_t reached_here = 0;
    constexpr std::size_t kBlock = 256;
    Real corner[3 * kBlock];
    std::uint8_t seen[kBlock];
    for (std::size_t begin = first; begin < last; begin += kBlock) {
      const std::size_t end = std::min(last, begin + kBlock);
      corner_distances(&state[begin], end - begin, corner, seen);
      for (std::size_t fi = begin; fi < end; ++fi) {
        const bool reached = state[fi].reached();
        reached_here += reached;
        const Index label = reached ? state[fi].source() : kInvalidIndex;
        const Triangle& t = tri.triangles()[fi];
        for (Index i = 0; i < 3; ++i) {
          const Real d = corner[3 * (fi - begin) + i];
          const std::uint8_t level = ((seen[fi - begin] >> i) & 1) && d < inf ? 0 : 1;
          const bool better = level < tier[t[i]] || (level == tier[t[i]] && d < dmin[t[i]]);
          dmin[t[i]] = better ? d : dmin[t[i]];
          label_of[t[i]] = better ? label : label_of[t[i]];
          tier[t[i]] = better ? level : tier[t[i]];
        }
      }
    }
    return reached_here;
  };
  std::vector<std::uint8_t> tier;
  const unsigned parts = detail::ranges_used(threads, nf);
  if (parts == 1) return scatter(0, nf, vmin, vlabel, tier);
  // Several threads: each takes a range of faces into minima of its own (the first into the
  // result), then the minima are merged per vertex, an earlier range winning ties: the same
  // values and labels as one thread.
  std::vector<std::vector<Real>> part_min(parts - 1);
  std::vector<std::vector<Index>> part_label(parts - 1);
  std::vector<std::vector<std::uint8_t>> part_tier(parts - 1);
  std::atomic<std::size_t> faces_reached{0};
  detail::for_ranges(parts, nf, [&](std::size_t begin, std::size_t end, unsigned part) {
    faces_reached += part == 0 ? scatter(begin, end, vmin, vlabel, tier)
                               : scatter(begin, end, part_min[part - 1], part_label[part - 1], part_tier[part - 1]);
  });
  detail::for_ranges(threads, nv, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t k = 0; k + 1 < parts; ++k)
      for (std::size_t v = begin; v < end; ++v) {
        const bool better = part_tier[k][v] < tier[v] || (part_tier[k][v] == tier[v] && part_min[k][v] < vmin[v]);
        vmin[v] = better ? part_min[k][v] : vmin[v];
        vlabel[v] = better ? part_label[k][v] : vlabel[v];
        tier[v] = better ? part_tier[k][v] : tier[v];
      }
  });
  return faces_reached;
}

template <class Real>
void GeodesicSolver::Impl::gather(const Triangulation& tri, const FaceRecord<Real>* state,
                                  const std::vector<VertexSeed>& vertex_seeds, bool relax,
                                  const GeodesicOptions& options, const std::vector<Real>& vmin,
                                  std::vector<Index>& vlabel, GeodesicResult& result, unsigned threads,
                                  const std::vector<detail::SourcePoint>* points) const {
  const std::size_t nf = mesh().num_faces(), nv = mesh().num_vertices();
  // A vertex source's own value is exact and wins ties against the faces (vertex_seeds: one
  // per vertex, as seed() left them).
  const std::vector<VertexSeed>& seeds = vertex_seeds;
  // Results in the input's order, gathered (sequential writes, reads in layout order), then the
  // few vertex sources on top.
  const double cutoff = options.max_distance;
  const double inf_d = std::numeric_limits<double>::infinity();
  result.vertex_distance.resize(nv);
  result.vertex_source.resize(nv);
  detail::for_ranges(threads, nv, [&](std::size_t begin, std::size_t end, unsigned) {
    for (std::size_t in = begin; in < end; ++in) {
      const Index v = maps.vertex_to_layout(Index(in));
      const double d = double(vmin[v]) * mean_edge;
      const bool keep = d <= cutoff;
      result.vertex_distance[in] = keep ? d : inf_d;
      result.vertex_source[in] = keep ? vlabel[v] : kInvalidIndex;
    }
  });
  for (const VertexSeed& vs : seeds) {
    // Exact (model units) unless a face or an edge found the vertex closer; after relaxation
    // vmin holds the seed itself rounded to the propagation's precision.
    if (!(vs.value <= double(vmin[vs.vertex]) * mean_edge * (relax ? 1 + 1e-6 : 1.0))) continue;
    const Index in = maps.vertex_to_input(vs.vertex);
    const bool keep = vs.value <= cutoff;
    result.vertex_distance[in] = keep ? vs.value : inf_d;
    result.vertex_source[in] = keep ? vs.label : kInvalidIndex;
  }
  // The vertices one input edge from a vertex source: that edge's length in double where it
  // is the shortest path (source_edges.hpp); a part of the relaxation.
  if (relax)
    for (const VertexSeed& e : detail::source_edge_values(input, skipped_face, seeds)) {
      const Index in = maps.vertex_to_input(e.vertex);
      if (!(e.value <= cutoff) || !detail::settles_to_edge<Real>(result.vertex_distance[in], e.value)) continue;
      result.vertex_distance[in] = e.value;
      result.vertex_source[in] = e.label;
    }
  // On the flipped triangulation the input faces' virtual sources are fitted to the vertex
  // values from the flipped faces' records (fitted_face_sources.hpp); the face values then
  // come from them.
  const bool fitted = options.want_face_sources && &tri != &input;
  if (fitted) fitted_face_sources<Real>(state, result, threads, points ? *points : std::vector<detail::SourcePoint>{});
  if (options.want_face_distances) {
    // Else on the flipped triangulation an input face's value comes from its corners'
    // distances (before the cutoff, the vertex sources included), by layout index.
    std::vector<double> vdist;
    if (&tri != &input && !fitted) {
      vdist.resize(nv);
      for (std::size_t v = 0; v < nv; ++v) vdist[v] = double(vmin[v]) * mean_edge;
      for (const VertexSeed& vs : seeds)
        if (vs.value <= vdist[vs.vertex]) vdist[vs.vertex] = vs.value, vlabel[vs.vertex] = vs.label;
    }
    result.face_distance.resize(nf);
    result.face_source.resize(nf);
    for (std::size_t in = 0; in < nf; ++in) {
      const Index fi = maps.face_to_layout(Index(in));
      double d = std::numeric_limits<double>::infinity();
      Index label = kInvalidIndex;
      if (&tri == &input) {
        const FaceRecord<Real>& st = state[fi];
        if (st.reached()) d = double(st.dT) * mean_edge, label = st.source();
      } else if (fitted) {
        const VirtualSource& vs = result.face_sources[in];
        const Triangle& t = mesh().triangles[fi];
        const Vec3 centroid = (1.0 / 3) * (mesh().positions[t[0]] + mesh().positions[t[1]] + mesh().positions[t[2]]);
        const double at = vs.sigma + distance(centroid, vs.position);
        if (vs.reached() && at <= cutoff) d = at, label = vs.source;
      } else {
        // The propagation ran on other faces: an input face gets the mean of its corners'
        // distances and the label of its nearest corner.
        const Triangle& t = mesh().triangles[fi];
        int best = 0;
        for (int i = 1; i < 3; ++i)
          if (vdist[t[i]] < vdist[t[best]]) best = i;
        const double mean = (vdist[t[0]] + vdist[t[1]] + vdist[t[2]]) / 3;
        if (std::isfinite(mean) && mean <= cutoff) d = mean, label = vlabel[t[best]];
      }
      result.face_distance[in] = d;
      result.face_source[in] = label;
    }
  }
  // A doubled face's copy left out reads as the face kept (the same triangle in 3D).
  if (options.want_face_distances)
    for (const auto& [copy, kept] : face_copies) {
      result.face_distance[copy] = result.face_distance[kept];
      result.face_source[copy] = result.face_source[kept];
    }
  if (options.want_face_sources && !fitted) {
    // Asked for fitted sources on a solver without flips (none needed, or intrinsic_delaunay
    // off): each face keeps its own, raised where it reads below the straight line from its
    // source, as a fitted one would be (fitted_face_sources.hpp).
    const bool keep_line = options.fitted_face_sources && options.targets.empty() && points;
    result.face_sources.resize(nf);
    detail::for_ranges(threads, nf, [&](std::size_t begin, std::size_t end, unsigned) {
      for (std::size_t fi = begin; fi < end; ++fi) {
        const FaceRecord<Real>& st = state[fi];
        if (!st.reached()) continue;
        VirtualSource& vs = result.face_sources[maps.face_to_input(Index(fi))];
        vs.position = detail::canonical_to_3d(mesh(), Index(fi), double(st.sx) * mean_edge, double(st.sy) * mean_edge);
        vs.sigma = double(st.sigma) * mean_edge;
        vs.source = st.source();
        if (!keep_line) continue;
        const Triangle& t = mesh().triangles[fi];
        const Vec3 corners3d[3] = {mesh().positions[t[0]], mesh().positions[t[1]], mesh().positions[t[2]]};
        vs.sigma += detail::raise_to_line(corners3d, vs.position, vs.sigma, vs.source, *points, line_scale);
      }
    });
    for (const auto& [copy, kept] : face_copies) result.face_sources[copy] = result.face_sources[kept];
  }
}

template <class Real>
void GeodesicSolver::Impl::gather_reached(const FaceRecord<Real>* state, const std::vector<VertexSeed>& vertex_seeds,
                                          LocalValues values) const {
  // The faces reached: those the propagation reached for the first time, and the seeded ones.
  for (Index f : values.faces) values.face_mark[f] = 1;
  for (Index f : values.seeded)
    if (!values.face_mark[f]) values.face_mark[f] = 1, values.faces.push_back(f);
  for (const VertexSeed& vs : vertex_seeds) values.touch(vs.vertex, vs.value, vs.label);
  // The faces' corners; those whose face does not see its source (corner_values.hpp) only
  // give the vertices that none of their faces gave a value: kept aside, then applied.
  std::vector<VertexSeed> unseen;
  for (Index f : values.faces) {
    const FaceRecord<Real>& st = state[f];
    const Triangle& t = input.triangles()[f];
    for (Index i = 0; i < 3; ++i) {
      const double d = double(corner_distance(st, i)) * mean_edge;
      if (corner_sees_source(st, i))
        values.touch(t[i], d, st.source());
      else
        unseen.push_back({t[i], d, st.source()});
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (VertexSeed& u : unseen)
    if (values.vdist[u.vertex] != inf) u.vertex = kInvalidIndex;   // a seen value stands
  for (const VertexSeed& u : unseen)
    if (u.vertex != kInvalidIndex) values.touch(u.vertex, u.value, u.label);
}

template <class Real>
void GeodesicSolver::Impl::gather_local(const FaceRecord<Real>* state, const LocalValues& values,
                                        const GeodesicOptions& options, LocalField& result) const {
  const double cutoff = options.max_distance;
  for (Index v : values.vertices) {
    if (!(values.vdist[v] <= cutoff)) continue;
    result.vertices.push_back(maps.vertex_to_input(v));
    result.vertex_distance.push_back(values.vdist[v]);
    result.vertex_source.push_back(values.vlabel[v]);
  }
  result.faces.reserve(values.faces.size());
  result.face_distance.reserve(values.faces.size());
  result.face_source.reserve(values.faces.size());
  if (options.want_face_sources) result.face_sources.reserve(values.faces.size());
  const double scaled_cutoff = cutoff / mean_edge;
  for (Index f : values.faces) {
    const FaceRecord<Real>& st = state[f];
    // Faces that cannot hold a point within max_distance (reached by the last ring of the
    // front) are left out of the result.
    if (!(double(st.dT) - double(detail::centroid_radius(st.len)) <= scaled_cutoff)) continue;
    result.faces.push_back(maps.face_to_input(f));
    result.face_distance.push_back(double(st.dT) * mean_edge);
    result.face_source.push_back(st.source());
    if (options.want_face_sources) {
      VirtualSource vs;
      vs.position = detail::canonical_to_3d(mesh(), f, double(st.sx) * mean_edge, double(st.sy) * mean_edge);
      vs.sigma = double(st.sigma) * mean_edge;
      vs.source = st.source();
      result.face_sources.push_back(vs);
    }
  }
}

}  // namespace gsp
