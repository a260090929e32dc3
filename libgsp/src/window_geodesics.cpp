#include <gsp/window_geodesics.hpp>

#include "intrinsic_delaunay.hpp"
#include "window_geodesics_impl.hpp"
#include "vertex_relaxation.hpp"

#include <gsp/connectivity.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/face_frame.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <stdexcept>
#include <string>
#include <tuple>

namespace gsp {

using namespace detail::windows;

namespace {

constexpr int kSamples = 7;
// Up to this many targets the propagation is goal-directed (the heuristic costs one distance
// per target and face); beyond, it only stops early.
constexpr std::size_t kGoalTargets = 16;

// The fans around each vertex (WindowGeodesics::Impl::corner_fan, joint): corners of one
// vertex are in one fan when their faces share an edge at the vertex that the propagation
// crosses (ring). A union-find over each vertex's few corners.
void find_fans(WindowGeodesics::Impl& m) {
  m.corner_fan.assign(m.corners.size(), 0);
  m.joint.assign(m.num_vertices, false);
  std::vector<Index> parent;
  for (std::size_t v = 0; v < m.num_vertices; ++v) {
    const Index begin = m.corner_begin[v], end = m.corner_begin[v + 1];
    if (end - begin < 2) continue;
    parent.resize(end - begin);
    for (Index i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](Index x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    auto local = [&](Index face) {   // the position of `face`'s corner at v in v's list
      for (Index c = begin; c < end; ++c)
        if (face_of(m.corners[c]) == face) return c - begin;
      return kInvalidIndex;
    };
    for (Index c = begin; c < end; ++c) {
      const Index corner = m.corners[c], f = face_of(corner);
      // the two edges at the corner: leaving it (halfedge `corner`) and arriving (the previous)
      for (Index h : {corner, prev_halfedge(corner)})
        for (Index g = m.ring[h]; g != h; g = m.ring[g]) {
          const Index o = local(face_of(g));
          if (o != kInvalidIndex && face_of(g) != f) parent[find(c - begin)] = find(o);
        }
    }
    std::vector<Index> number(parent.size(), kInvalidIndex);
    Index fans = 0;
    for (Index i = 0; i < parent.size(); ++i) {
      const Index r = find(i);
      if (number[r] == kInvalidIndex) number[r] = fans++;
      m.corner_fan[begin + i] = number[r];
    }
    m.joint[v] = fans > 1;
  }
}

}  // namespace

WindowGeodesics::WindowGeodesics(const TriangleMesh& mesh, bool intrinsic_delaunay)
    : WindowGeodesics(mesh, build_connectivity(mesh), intrinsic_delaunay) {}

WindowGeodesics::WindowGeodesics(const TriangleMesh& mesh, const Connectivity& conn, bool intrinsic_delaunay)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.num_vertices = mesh.positions.size();
  m.positions = &mesh.positions;
  m.intrinsic = intrinsic_delaunay;
  m.input_triangles = &mesh.triangles;
  m.skipped = intrinsic::skipped_faces(mesh, conn);   // doubled faces too
  const std::vector<bool>& skipped = m.skipped;
  std::vector<double> length = intrinsic::halfedge_lengths(mesh);
  intrinsic::snap_zero_lengths(length);
  m.input_length = length;
  m.mean_edge = intrinsic::mean_edge_length(length, skipped);
  if (m.mean_edge > 0 && std::isfinite(m.mean_edge)) {
    int e = 0;
    std::frexp(m.mean_edge, &e);   // mean_edge = f 2^e, f in [1/2, 1)
    m.unit = std::ldexp(1.0, -e);
    for (double& l : length) l *= m.unit;
    for (double& l : m.input_length) l *= m.unit;
    m.mean_edge *= m.unit;
  }
  m.ring.resize(conn.num_halfedges());
  for (Index h = 0; h < m.ring.size(); ++h) m.ring[h] = intrinsic::next_crossed(conn, skipped, length, h);
  m.input_corner_begin = conn.vertex_corner_begin;
  m.input_corners = conn.vertex_corners;
  {
    detail::IntrinsicTriangulation t;
    t.triangles = mesh.triangles;
    t.length = std::move(length);
    t.skipped = skipped;
    t.positions = &mesh.positions;
    t.ring = std::move(m.ring);
    if (intrinsic_delaunay) {
      // The same flips as GSP's solver (intrinsic_delaunay.hpp): slivers become well-shaped
      // triangles of the same surface.
      detail::make_intrinsic_delaunay(t, 20 * t.length.size());
    } else if (detail::orient_consistently(t) > 0) {
      // The input's faces wound alike per patch too, as the flips' first step winds them: the
      // windows' near-ties are decided by each face's winding, so a soup with some faces
      // reversed had a field of its own (a house STL with 30% reversed: 2.9% apart at a
      // vertex, paths 6.6% over the field on average against 5.1% as read). A face wound the
      // other way keeps corner 0 and swaps 1 and 2 (`rewound`).
      m.rewound.resize(t.triangles.size());
      for (std::size_t f = 0; f < t.triangles.size(); ++f) m.rewound[f] = t.triangles[f][1] != mesh.triangles[f][1];
    }
    m.triangles = std::move(t.triangles), length = std::move(t.length), m.ring = std::move(t.ring);
  }
  m.frame.resize(m.triangles.size());
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    // the core's canonical frame (face_frame.hpp): corner 0 at the origin, corner 1 on +x
    const intrinsic::EdgeView<double> v = intrinsic::edge_view(&length[3 * f], 0);
    m.frame[f] = {V2{0, 0}, V2{v.e1, 0}, V2{v.px, v.py}};
  }
  // vertex -> corners of the propagation's faces (the flips moved them off the input's)
  m.corner_begin.assign(m.num_vertices + 1, 0);
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    if (!skipped[f])
      for (Index v : m.triangles[f]) ++m.corner_begin[v + 1];
  for (std::size_t v = 0; v < m.num_vertices; ++v) m.corner_begin[v + 1] += m.corner_begin[v];
  m.corners.resize(m.corner_begin.back());
  std::vector<Index> fill(m.corner_begin.begin(), m.corner_begin.end() - 1);
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    if (!skipped[f])
      for (Index i = 0; i < 3; ++i) m.corners[fill[m.triangles[f][i]]++] = Index(3 * f + i);
  find_fans(m);
}

WindowGeodesics::~WindowGeodesics() = default;
WindowGeodesics::WindowGeodesics(WindowGeodesics&&) noexcept = default;
WindowGeodesics& WindowGeodesics::operator=(WindowGeodesics&&) noexcept = default;

std::vector<double> WindowGeodesics::distances_from_vertex(Index source, const WindowOptions& options,
                                                           WindowStats* stats) const {
  return distances({source}, options, stats);
}

bool WindowGeodesics::on_input_faces() const { return !impl_->intrinsic; }

std::vector<double> WindowGeodesics::distances(const std::vector<Index>& sources, const WindowOptions& options,
                                               WindowStats* stats, std::vector<Index>* label) const {
  std::vector<Source> points;
  points.reserve(sources.size());
  for (Index v : sources) points.push_back(Source::at_vertex(v));
  WindowField f = field(points, options, stats);
  if (label) *label = std::move(f.vertex_source);
  return std::move(f.vertex_distance);
}

WindowField WindowGeodesics::field(const std::vector<Source>& sources, const WindowOptions& options,
                                   WindowStats* stats) const {
  const Impl& mesh = *impl_;
  const auto& frame = mesh.frame;
  const std::size_t nv = mesh.num_vertices, nf = mesh.triangles.size();
  if (sources.empty()) throw std::invalid_argument("no source vertex");
  for (const Source& source : sources) {
    if (source.offset != 0) throw std::invalid_argument("window propagation: sources with an offset are not supported");
    if (source.kind == Source::Kind::vertex) {
      if (source.element >= nv) throw std::invalid_argument("source vertex " + std::to_string(source.element) + " out of range");
      continue;
    }
    if (mesh.intrinsic) throw std::invalid_argument("window propagation on intrinsic faces: vertex sources only");
    if (source.element >= nf || (mesh.skipped[source.element] && repeats_vertex(mesh.triangles[source.element])))
      throw std::invalid_argument("source face " + std::to_string(source.element) + " out of range or degenerate");
    for (double b : source.barycentric)
      if (!(b >= 0) || !std::isfinite(b)) throw std::invalid_argument("source barycentric weights must be >= 0");
  }
  for (Index t : options.targets)
    if (t >= nv) throw std::invalid_argument("target vertex " + std::to_string(t) + " out of range");
  const unsigned k = options.windows;
  if (k < 1 || k > 8) throw std::invalid_argument("windows per face: 1 to 8, not " + std::to_string(k));

  WindowField result;
  result.data_ = std::make_unique<WindowField::Data>();
  WindowField::Data& data = *result.data_;
  data.mesh = &mesh, data.k = k;
  // Windows only for the faces reached (a path's propagation stops early): a block of k per face.
  data.block.assign(nf, kInvalidIndex);
  data.count.assign(nf, 0);
  std::vector<Window>& win = data.win;
  std::vector<Index>& block = data.block;
  std::vector<std::uint8_t>& count = data.count;
  std::vector<std::uint32_t> stamp(nf, 0);
  // Per face, one bit per slot: the window in it was stepped into the neighbours at a pop
  // since it last changed. A face popped again sends only its new or changed windows (the
  // others' offers would change nothing: a neighbour's slots only get better).
  std::vector<std::uint8_t> sent(nf, 0);
  auto samples = [&](Index f) {
    const auto& c = frame[f];
    return std::array<V2, kSamples>{c[0], c[1], c[2], (1.0 / 3) * (c[0] + c[1] + c[2]), 0.5 * (c[0] + c[1]),
                                    0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0])};
  };
  using Values = std::array<double, kSamples>;
  auto values = [&](const Window& w, const std::array<V2, kSamples>& pts) {
    Values v;
    for (int i = 0; i < kSamples; ++i) v[i] = value_at(w, pts[i]);
    return v;
  };
  // Per slot: its window's values at the face's samples (computed once, when the slot is
  // written); per block: the least of them at each sample.
  std::vector<Values> slot_values;
  std::vector<Values> least;
  auto face_min = [&](Index f) {
    Values m;
    m.fill(kInf);
    for (unsigned i = 0; i < count[f]; ++i) {
      const Values& v = slot_values[block[f] * k + i];
      for (int j = 0; j < kSamples; ++j) m[j] = std::min(m[j], v[j]);
    }
    return m;
  };
  using Entry = std::tuple<double, Index, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  // With a few targets the order is A*'s: a face's key plus a lower bound of the distance from
  // any of its points to the nearest target (the straight line from its first corner, less
  // its longest edge: a point of the face is no farther than that from the corner).
  const bool goal_directed = !options.targets.empty() && options.targets.size() <= kGoalTargets;
  auto heuristic = [&](Index f) {
    if (!goal_directed) return 0.0;
    const auto& c = frame[f];
    const double longest = std::max({norm(c[1] - c[0]), norm(c[2] - c[1]), norm(c[0] - c[2])});
    const Vec3 x = (*mesh.positions)[mesh.triangles[f][0]];
    double h = kInf;
    for (Index t : options.targets) h = std::min(h, mesh.unit * gsp::distance(x, (*mesh.positions)[t]));
    return std::max(0.0, h - longest);
  };
  auto push = [&](Index f) {
    const Values& m = least[block[f]];
    queue.emplace(*std::min_element(m.begin(), m.end()) + heuristic(f), f, ++stamp[f]);
  };
  std::size_t updates = 0;

  // Scratch windows, made once per query: a Window default-initialises its 120 bytes, and made
  // at every offer's merge and every step's outputs that zeroing was the query's largest item
  // (docs/benchmarks.md, "One constant factor"). merge() and step() assign whole windows to
  // what they return, so nothing stale is read.
  Window merged;
  Window out[kMaxStepOut];
  // Offers window w to face g; true when the face changed.
  auto offer = [&](Index g, const Window& w) {
    const auto pts = samples(g);
    if (block[g] == kInvalidIndex) {
      const Values first = values(w, pts);
      if (std::none_of(first.begin(), first.end(), [](double x) { return x < kInf; })) return false;
      block[g] = Index(least.size());
      least.push_back(first);
      win.resize(win.size() + k);
      slot_values.resize(win.size());
      win[block[g] * k] = w;
      slot_values[block[g] * k] = first;
      count[g] = 1;
      sent[g] = 0;
      return ++updates, true;
    }
    Window* slots = &win[block[g] * k];
    Values* slot_v = &slot_values[block[g] * k];
    Values& cur = least[block[g]];
    for (unsigned i = 0; i < count[g]; ++i) {
      const int m = merge(slots[i], w, &merged);
      if (m == 0) continue;
      if (m == 1) return false;
      slots[i] = merged;
      slot_v[i] = values(merged, pts);
      sent[g] &= std::uint8_t(~(1u << i));
      const Values after = face_min(g);
      bool better = false;
      for (int j = 0; j < kSamples; ++j) better |= after[j] < cur[j] * (1 - 1e-9);
      cur = after;
      return better ? (++updates, true) : false;
    }
    const Values nv_ = values(w, pts);
    bool better = false;
    for (int j = 0; j < kSamples; ++j) better |= nv_[j] < cur[j] * (1 - 1e-9);
    if (!better && options.own_points) {
      // No sample gains, but the part of the face the window sees may hold none (a sliver):
      // compare at its own point.
      const double own = value_at(w, w.mid);
      double held = kInf;
      for (unsigned i = 0; i < count[g]; ++i) held = std::min(held, value_at(slots[i], w.mid));
      better = own < held * (1 - 1e-9);
    }
    if (!better) return false;
    if (count[g] < k) {
      sent[g] &= std::uint8_t(~(1u << count[g]));
      slot_v[count[g]] = nv_;
      slots[count[g]++] = w;
      for (int j = 0; j < kSamples; ++j) cur[j] = std::min(cur[j], nv_[j]);
      return ++updates, true;
    }
    // Full: keep the k of the k + 1 windows that leave the fewest points unreached, then the
    // lowest sum, over the samples and each window's own point; the new one must be among them.
    std::array<Values, 9> all;
    for (unsigned i = 0; i < k; ++i) all[i] = slot_v[i];
    all[k] = nv_;
    std::array<std::array<double, 9>, 9> at_mid;   // at_mid[i][j]: window i at window j's point
    const unsigned points = options.own_points ? k + 1 : 0;
    for (unsigned i = 0; i <= k; ++i)
      for (unsigned j = 0; j < points; ++j) {
        const Window& wi = i < k ? slots[i] : w;
        at_mid[i][j] = value_at(wi, j < k ? slots[j].mid : w.mid);
      }
    int best_drop = -1;
    std::pair<int, double> best_key{kSamples + 10, kInf};
    Values best_min{};
    for (unsigned drop = 0; drop <= k; ++drop) {
      Values m;
      m.fill(kInf);
      std::array<double, 9> mm;
      mm.fill(kInf);
      for (unsigned i = 0; i <= k; ++i)
        if (i != drop) {
          for (int j = 0; j < kSamples; ++j) m[j] = std::min(m[j], all[i][j]);
          for (unsigned j = 0; j < points; ++j) mm[j] = std::min(mm[j], at_mid[i][j]);
        }
      std::pair<int, double> key{0, 0.0};
      for (double x : m) x < kInf ? key.second += x : ++key.first;
      for (unsigned j = 0; j < points; ++j) mm[j] < kInf ? key.second += mm[j] : ++key.first;
      if (key < best_key) best_key = key, best_drop = int(drop), best_min = m;
    }
    if (best_drop == int(k)) return false;
    slots[best_drop] = w;
    slot_v[best_drop] = nv_;
    sent[g] &= std::uint8_t(~(1u << best_drop));
    cur = best_min;
    return ++updates, true;
  };

  for (std::size_t k_src = 0; k_src < sources.size(); ++k_src) {
    const Source& source = sources[k_src];
    if (source.kind != Source::Kind::vertex) {
      // A point of a face sees all of it, as a corner does (a doubled face's point: in the
      // copy kept).
      std::array<double, 3> b = source.barycentric;
      const Index face = intrinsic::kept_copy(*mesh.input_triangles, mesh.input_corner_begin, mesh.input_corners,
                                              mesh.skipped, source.element, b);
      mesh.to_propagation_corners(face, b);
      const auto& c = frame[face];
      const double sum = b[0] + b[1] + b[2];
      if (!(sum > 0)) throw std::invalid_argument("source barycentric weights sum to 0");
      Window w = corner_window((b[0] / sum) * c[0] + (b[1] / sum) * c[1] + (b[2] / sum) * c[2], 0.0);
      w.label = Index(k_src);
      if (offer(face, w)) push(face);
      continue;
    }
    for (Index c = mesh.corner_begin[source.element]; c < mesh.corner_begin[source.element + 1]; ++c) {
      const Index corner = mesh.corners[c], f = face_of(corner);
      Window w = corner_window(frame[f][corner_of(corner)], 0.0);
      w.label = Index(k_src);
      if (offer(f, w)) push(f);
    }
  }

  // With targets: their least value over the samples at their corners (+inf until reached).
  auto targets_bound = [&] {
    double bound = 0;
    for (Index t : options.targets) {
      double d = kInf;
      for (Index c = mesh.corner_begin[t]; c < mesh.corner_begin[t + 1]; ++c)
        if (const Index b = block[face_of(mesh.corners[c])]; b != kInvalidIndex)
          d = std::min(d, least[b][corner_of(mesh.corners[c])]);
      bound = std::max(bound, d);
    }
    return bound;
  };
  std::size_t pops = 0;
  double complete_to = kInf;   // stopped early: values up to here are final
  while (!queue.empty()) {
    const auto [key, f, st] = queue.top();
    queue.pop();
    if (st != stamp[f]) continue;
    if (!options.targets.empty() && (++pops & 31) == 0 && key > targets_bound() + 2 * mesh.mean_edge) {
      complete_to = key;
      break;
    }
    for (Index i = 0; i < 3; ++i) {
      const Index h = 3 * f + i;
      const Index va = mesh.triangles[f][i];
      const V2 fa = frame[f][i], fb = frame[f][(i + 1) % 3], fc = frame[f][(i + 2) % 3];
      const double len = norm(fb - fa);
      if (!(len > 0)) continue;
      const V2 uf = (1 / len) * (fb - fa);
      const double side_f = cross(uf, fc - fa) >= 0 ? 1.0 : -1.0;
      for (Index g_h = mesh.ring[h]; g_h != h; g_h = mesh.ring[g_h]) {
        const Index g = face_of(g_h), j = corner_of(g_h);
        if (g == f) continue;
        // g's corners: A = the one at va, B at vb, P the third
        const bool same_dir = mesh.triangles[g][j] == va;
        const Index ja = same_dir ? j : (j + 1) % 3, jb = same_dir ? (j + 1) % 3 : j;
        const V2 ga = frame[g][ja], gb = frame[g][jb], gp = frame[g][3 - ja - jb];
        const double len_g = norm(gb - ga);
        if (!(len_g > 0)) continue;
        const V2 ug = (1 / len_g) * (gb - ga);
        V2 ng{-ug.y, ug.x};
        if (dot(ng, gp - ga) < 0) ng = -1.0 * ng;
        // f's frame -> g's frame: the same point of the edge, the other side of it
        auto map = [&](V2 q) {
          const V2 d = q - fa;
          return ga + dot(d, uf) * ug - (cross(uf, d) * side_f) * ng;
        };
        bool changed = false;
        for (unsigned w = 0; w < count[f]; ++w) {
          if (sent[f] >> w & 1u) continue;
          const Window& src = win[block[f] * k + w];
          Window t = src;
          t.s = map(src.s);
          if (src.rays)
            for (int r = 0; r < 2; ++r) t.w[r] = map(src.w[r]), t.u[r] = map(src.u[r]);
          const int n = step(t, ga, gb, gp, out, options.shadow_sources);
          for (int o = 0; o < n; ++o) changed |= offer(g, out[o]);
        }
        if (changed) push(g);
      }
    }
    // At a joint vertex the faces of its other fans share no edge with f: they get the
    // vertex's value from f as a corner window (a path through the vertex is on the surface).
    for (Index i = 0; i < 3; ++i) {
      const Index v = mesh.triangles[f][i];
      if (!mesh.joint[v]) continue;
      double at = kInf;
      Index label = kInvalidIndex;
      for (unsigned w = 0; w < count[f]; ++w) {
        const Window& x = win[block[f] * k + w];
        if (const double d = value_at(x, frame[f][i]); d < at) at = d, label = x.label;
      }
      if (!(at < kInf)) continue;
      Index own = kInvalidIndex;
      for (Index c = mesh.corner_begin[v]; c < mesh.corner_begin[v + 1]; ++c)
        if (mesh.corners[c] == 3 * f + i) own = mesh.corner_fan[c];
      for (Index c = mesh.corner_begin[v]; c < mesh.corner_begin[v + 1]; ++c) {
        if (mesh.corner_fan[c] == own) continue;
        const Index g = face_of(mesh.corners[c]);
        Window w = corner_window(frame[g][corner_of(mesh.corners[c])], at);
        w.label = label;
        if (offer(g, w)) push(g);
      }
    }
    sent[f] = std::uint8_t((1u << count[f]) - 1);
  }

  std::vector<double> dist(nv, kInf);
  std::vector<Index> from(nv, kInvalidIndex);
  std::size_t reached = 0, relaxed = 0;
  for (Index f = 0; f < nf; ++f) {
    if (count[f] > 0) ++reached;
    for (unsigned w = 0; w < count[f]; ++w)
      for (int c = 0; c < 3; ++c) {
        const Index v = mesh.triangles[f][c];
        const Window& x = win[block[f] * k + w];
        const double d = value_at(x, frame[f][c]);
        if (d < dist[v]) dist[v] = d, from[v] = x.label;
      }
  }
  for (std::size_t k_src = 0; k_src < sources.size(); ++k_src)
    if (sources[k_src].kind == Source::Kind::vertex) dist[sources[k_src].element] = 0, from[sources[k_src].element] = Index(k_src);
  // Along the input's edges, with GSP's own relaxation (vertex_relaxation.hpp): a value above
  // the shortest edge path (a window lost where a face kept others, a vertex the windows do
  // not reach across a vertex-only joint) takes that path, which is on the surface too.
  detail::relax_along_edges<double>(*mesh.input_triangles, mesh.input_length, 1.0, mesh.skipped,
                                    mesh.input_corner_begin, mesh.input_corners, nullptr, complete_to, 0.0, dist, from,
                                    relaxed);
  if (stats) stats->window_updates = updates, stats->faces_reached = reached, stats->relaxed = relaxed;
  for (double& d : dist) d /= mesh.unit;
  result.vertex_distance = std::move(dist);
  result.vertex_source = std::move(from);
  return result;
}

}  // namespace gsp
