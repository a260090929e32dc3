#pragma once
// Vertices as pseudo-sources (internal): the per-vertex distances of a finished propagation
// relaxed along the input's edges, and the vertices that this lowers seeded as virtual sources
// for another propagation round.
//
// Why: a face keeps one virtual source, the one nearest its centroid, and its corners take
// their distances from it. Where faces are large and the front is anisotropic (CAD parts,
// fans round poles, soups joined at single vertices) the source that wins a face's centroid
// is not the best one for every corner, and a corner can end up farther than the path along
// one mesh edge from its neighbour: more than Dijkstra, which no geodesic method should be.
// Exact window propagation treats a vertex the front reaches as a pseudo-source carrying its
// distance; here a vertex whose distance an edge lowers becomes one: its fan is seeded with a
// source at the vertex (sigma = its distance) and the propagation resumes from there. Each
// round only lowers distances, each value stays the length of a path on the surface, and no
// vertex ends farther than the shortest edge path (tests/geodesic_bounds_test.cpp).
#include "face_record.hpp"
#include "parallel_ranges.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/mesh.hpp>

#include <algorithm>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace gsp::detail {

// Lowers d[b] to d[a] + |ab| along the edges of `triangles` (lengths per halfedge, scaled to
// the propagation's units), Dijkstra-ordered from every edge where that shortens something
// (from == nullptr) or from the edges at the vertices `from` lists, never past `limit`. Labels
// follow the value. Returns the vertices lowered by more than the relative `gain` (each once):
// those worth a new propagation round; the others keep their new value only. `relaxed` counts
// every lowering; `reached`, when given, gets every vertex that had no value before.
template <class Real>
std::vector<Index> relax_along_edges(const std::vector<Triangle>& triangles, const std::vector<double>& length,
                                     double scale, const std::vector<bool>& skipped_face,
                                     const std::vector<Index>& corner_begin, const std::vector<Index>& corners,
                                     const std::vector<Index>* from, Real limit, Real gain, std::vector<Real>& d,
                                     std::vector<Index>& label, std::size_t& relaxed,
                                     std::vector<Index>* reached = nullptr, unsigned threads = 1) {
  // A clearly shorter value only: rounding must not make two vertices lower each other forever.
  constexpr Real kMargin = 1 - 8 * std::numeric_limits<Real>::epsilon();
  using Item = std::pair<Real, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  std::vector<Index> lowered;
  auto offer = [&](Index a, Index to, Real len) {
    const Real candidate = d[a] + len;
    if (!(candidate < d[to] * kMargin) || !(candidate <= limit)) return;
    if (candidate < d[to] * (1 - gain)) lowered.push_back(to);
    if (reached && d[to] == std::numeric_limits<Real>::infinity()) reached->push_back(to);
    ++relaxed;
    d[to] = candidate;
    label[to] = label[a];
    heap.push({candidate, to});
  };
  // Offers v's distance to its neighbours along the faces at v.
  auto expand = [&](Index v) {
    for (Index k = corner_begin[v]; k < corner_begin[v + 1]; ++k) {
      const Index c = corners[k];
      const Index f = face_of(c);
      if (skipped_face[f]) continue;
      const Index j = corner_of(c), jn = j == 2 ? 0 : j + 1, jp = j == 0 ? 2 : j - 1;
      offer(v, triangles[f][jn], Real(length[3 * f + j] * scale));
      offer(v, triangles[f][jp], Real(length[3 * f + jp] * scale));
    }
  };
  if (from) {
    for (Index v : *from) expand(v);
  } else {
    // Whether edge i of face f lowers one of its ends. Almost never true: one predictable test
    // per edge (which end is nearer is a coin toss the branch predictor loses;
    // docs/performance.md, "Single-thread propagation", item 8).
    auto shortens = [&](std::size_t f, Index i) {
      const Triangle& t = triangles[f];
      const Real len = Real(length[3 * f + i] * scale);
      const Real da = d[t[i]], db = d[t[i == 2 ? 0 : i + 1]];
      return da + len < db * kMargin || db + len < da * kMargin;
    };
    auto scan = [&](std::size_t f) {
      if (skipped_face[f]) return;
      for (Index i = 0; i < 3; ++i) {
        if (!shortens(f, i)) continue;
        const Index a = triangles[f][i], b = triangles[f][i == 2 ? 0 : i + 1];
        const Real len = Real(length[3 * f + i] * scale);
        d[a] < d[b] ? offer(a, b, len) : offer(b, a, len);
      }
    };
    if (threads <= 1) {
      for (std::size_t f = 0; f < triangles.size(); ++f) scan(f);
    } else {
      // Several threads find the few faces with such an edge (reading only), then those are
      // scanned in order as above; an edge a lowering makes shorter later is offered when its
      // lowered end is expanded.
      std::vector<std::vector<Index>> found(threads);
      for_ranges(threads, triangles.size(), [&](std::size_t begin, std::size_t end, unsigned part) {
        for (std::size_t f = begin; f < end; ++f)
          if (!skipped_face[f] && (shortens(f, 0) || shortens(f, 1) || shortens(f, 2)))
            found[part].push_back(Index(f));
      });
      for (const std::vector<Index>& part : found)
        for (Index f : part) scan(f);
    }
  }
  while (!heap.empty()) {
    const auto [value, v] = heap.top();
    heap.pop();
    if (value > d[v]) continue;   // lowered again since
    expand(v);
  }
  std::sort(lowered.begin(), lowered.end());
  lowered.erase(std::unique(lowered.begin(), lowered.end()), lowered.end());
  return lowered;
}

}  // namespace gsp::detail
