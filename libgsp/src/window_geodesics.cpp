#include <gsp/window_geodesics.hpp>

#include "intrinsic_delaunay.hpp"
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

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSamples = 7;

struct V2 {
  double x = 0, y = 0;
};
V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
V2 operator*(double t, V2 a) { return {t * a.x, t * a.y}; }
double cross(V2 a, V2 b) { return a.x * b.y - a.y * b.x; }
double dot(V2 a, V2 b) { return a.x * b.x + a.y * b.y; }
// sqrt, not std::hypot: hypot guards against overflow at 1e154 and took 42% of a query here.
double norm(V2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

// Shadow kinds beyond a ray: none, a wedge bounded by W -> U, or all of the face (W is one of
// its corners).
enum : std::uint8_t { kNoShadow = 0, kBounded = 1, kWholeFace = 2 };

struct Window {
  V2 s;
  double sigma = 0;
  Index label = 0;     // which source it comes from
  bool rays = false;   // false: S is a corner of the face and sees all of it
  V2 w[2], u[2];
  std::uint8_t shadow[2] = {kNoShadow, kNoShadow};
};

Window corner_window(V2 corner, double value) {
  Window w;
  w.s = corner, w.sigma = value;
  return w;
}

double ray_side(const Window& win) { return cross(win.w[0] - win.s, win.w[1] - win.s); }

bool beyond_ray(const Window& win, int r, V2 p, double o) {
  const double c = cross(win.w[r] - win.s, p - win.s) * o;
  const double tol = 1e-12 * std::abs(o) * (1 + norm(p - win.s));
  return r == 0 ? c < -tol : c > tol;
}

// Whether p (beyond ray r) lies in the shadow wedge at W: between the ray's continuation past
// W and the ray W -> U. A wedge of no width (U on the continuation: collinear vertices, as on
// CAD grids) holds nothing; its cross products are rounding noise of either sign.
bool in_shadow(const Window& win, int r, V2 p) {
  if (win.shadow[r] == kNoShadow) return false;
  if (win.shadow[r] == kWholeFace) return true;
  const V2 w = win.w[r], u = win.u[r], d = w - win.s;
  const double side = cross(d, u - w);
  if (!(std::abs(side) > 1e-12 * norm(d) * norm(u - w))) return false;
  const double sgn = side > 0 ? 1.0 : -1.0, tol = 1e-12 * norm(p - w);
  return sgn * cross(d, p - w) >= -tol * norm(d) && sgn * cross(u - w, p - w) <= tol * norm(u - w);
}

// Whether the window's two rays bound a wedge of some width (collinear vertices can make them
// coincide; such a window sees nothing).
bool has_width(const Window& win) {
  return std::abs(ray_side(win)) > 1e-12 * norm(win.w[0] - win.s) * norm(win.w[1] - win.s);
}

// Windows with rays have width (step() makes no other), so the ray tests below are sound.
double value_at(const Window& win, V2 p) {
  if (win.rays) {
    const double o = ray_side(win);
    for (int r = 0; r < 2; ++r)
      if (beyond_ray(win, r, p, o))
        return in_shadow(win, r, p) ? norm(p - win.w[r]) + norm(win.w[r] - win.s) + win.sigma : kInf;
  }
  return norm(p - win.s) + win.sigma;
}

// The shadow wedge at ray r's vertex for the next face, whose entry edge has its shadowed part
// from the end X to the ray's crossing (which lies on the wedge's other side, the ray's
// continuation).
std::pair<std::uint8_t, V2> clip_shadow(const Window& win, int r, V2 x) {
  if (win.shadow[r] == kNoShadow) return {kNoShadow, {}};
  if (win.shadow[r] == kWholeFace) return {kBounded, x};
  const V2 w = win.w[r], u = win.u[r], d = w - win.s;
  const double side = cross(d, u - w);
  if (!(std::abs(side) > 1e-12 * norm(d) * norm(u - w))) return {kNoShadow, {}};   // no width
  const double sgn = side > 0 ? 1.0 : -1.0;
  if (sgn * cross(u - w, x - w) <= 0) return {kBounded, x};   // X inside: bounded by W -> X now
  return {kBounded, u};
}

// The window `win` (in T's frame) through T's edge A B into T (P its third corner): at most
// two new windows.
int step(const Window& win, V2 a, V2 b, V2 p, Window out[2], int depth = 0) {
  const V2 ab = b - a;
  const double inside = cross(ab, p - a);
  int n = 0;
  auto corners = [&] {
    for (V2 x : {a, b}) {
      const double v = value_at(win, x);
      if (v < kInf) out[n] = corner_window(x, v), out[n++].label = win.label;
    }
    return n;
  };
  if (!(cross(ab, win.s - a) * inside < 0)) return corners();   // S on T's side: bend at A or B
  double lo = 0, hi = 1;
  V2 anchor[2] = {a, b};
  int from_ray[2] = {-1, -1}, hidden_by = -1;
  if (win.rays) {
    const double o = ray_side(win);
    for (int r = 0; r < 2; ++r) {
      const double sgn = r == 0 ? 1 : -1;
      const V2 wv = win.w[r];
      const double ca = sgn * cross(wv - win.s, a - win.s) * o, cb = sgn * cross(wv - win.s, b - win.s) * o;
      if (ca >= 0 && cb >= 0) continue;
      if (ca < 0 && cb < 0) {
        lo = 1, hi = 0, hidden_by = r;
        break;
      }
      const double t = ca / (ca - cb);
      if (ca < 0) {
        if (t > lo) lo = t, anchor[0] = wv, from_ray[0] = r;
      } else if (t < hi) {
        hi = t, anchor[1] = wv, from_ray[1] = r;
      }
    }
  }
  if (!(hi - lo > 1e-9)) {
    // S sees nothing of AB. Behind the ray that hides it, its vertex W is the source, seen
    // through its shadow wedge (W a corner of the sending face sees all of AB); without a
    // wedge there, the bends at A and B.
    if (hidden_by < 0 || win.shadow[hidden_by] == kNoShadow || depth > 0) return corners();
    const V2 w = win.w[hidden_by];
    Window sw;
    sw.s = w, sw.sigma = win.sigma + norm(w - win.s), sw.label = win.label;
    if (win.shadow[hidden_by] == kBounded) {
      sw.rays = true;
      sw.w[0] = w + (w - win.s), sw.w[1] = win.u[hidden_by];   // the ray's continuation, W -> U
    }
    const int m = step(sw, a, b, p, out, depth + 1);
    return m > 0 ? m : corners();
  }
  Window nw;
  nw.s = win.s, nw.sigma = win.sigma, nw.rays = true, nw.label = win.label;
  nw.w[0] = anchor[0], nw.w[1] = anchor[1];
  const V2 ends[2] = {a, b};
  for (int e = 0; e < 2; ++e) {
    if (from_ray[e] < 0) {
      nw.shadow[e] = kWholeFace;
    } else {
      const auto [kind, u] = clip_shadow(win, from_ray[e], ends[e]);
      nw.shadow[e] = kind, nw.u[e] = u;
    }
  }
  if (has_width(nw)) out[n++] = nw;   // a window of no width sees nothing
  return n;
}

bool same_source(const Window& x, const Window& y) {
  return std::abs(x.sigma - y.sigma) <= 1e-9 * (1 + y.sigma) &&
         norm(x.s - y.s) <= 1e-9 * (1 + std::max(std::abs(y.s.x), std::abs(y.s.y)));
}

// The union of two windows of one source whose wedges touch or overlap: 1 (x already holds
// it), 2 (merged into *out), 0 (no union).
int merge(const Window& x, const Window& y, Window* out) {
  if (!same_source(x, y)) return 0;
  if (!x.rays) return 1;
  if (!y.rays) return *out = y, 2;
  const V2 s = y.s;
  V2 ref = 0.5 * (x.w[0] + x.w[1]) - s;
  const double len = norm(ref);
  if (len > 0) ref = (1 / len) * ref;
  auto angle = [&](V2 v) { return std::atan2(cross(ref, v - s), dot(ref, v - s)); };
  struct End {
    double angle;
    const Window* win;
    int ray;
  };
  auto ends = [&](const Window& w) {
    End e0{angle(w.w[0]), &w, 0}, e1{angle(w.w[1]), &w, 1};
    return e0.angle <= e1.angle ? std::pair{e0, e1} : std::pair{e1, e0};
  };
  const auto [lx, hx] = ends(x);
  const auto [ly, hy] = ends(y);
  constexpr double tol = 1e-9;
  if (ly.angle > hx.angle + tol || lx.angle > hy.angle + tol) return 0;
  const End lo = lx.angle <= ly.angle ? lx : ly, hi = hx.angle >= hy.angle ? hx : hy;
  if (hi.angle - lo.angle >= M_PI - 1e-6) return 0;
  Window m;
  m.s = s, m.sigma = y.sigma, m.rays = true, m.label = y.label;
  for (int slot = 0; slot < 2; ++slot) {
    const End& e = slot == 0 ? lo : hi;
    m.w[slot] = e.win->w[e.ray], m.u[slot] = e.win->u[e.ray], m.shadow[slot] = e.win->shadow[e.ray];
  }
  *out = m;
  return 2;
}

}  // namespace

struct WindowGeodesics::Impl {
  std::size_t num_vertices = 0;
  // The input's edges for the final relaxation (vertex_relaxation.hpp): its triangles (the
  // caller keeps the mesh), their halfedge lengths, skipped faces and vertex -> corner lists.
  const std::vector<Triangle>* input_triangles = nullptr;
  std::vector<double> input_length;
  std::vector<bool> skipped;
  std::vector<Index> input_corner_begin, input_corners;
  std::vector<Triangle> triangles;        // the propagation's faces (intrinsic Delaunay or input)
  std::vector<Index> ring;                // per halfedge: the next face's halfedge on its edge
  std::vector<std::array<V2, 3>> frame;   // per face: its corners in its own plane
  std::vector<Index> corner_begin, corners;   // vertex -> corners 3 f + i, CSR
};

WindowGeodesics::WindowGeodesics(const TriangleMesh& mesh, bool intrinsic_delaunay)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.num_vertices = mesh.positions.size();
  m.input_triangles = &mesh.triangles;
  m.skipped = intrinsic::skipped_faces(mesh);
  const std::vector<bool>& skipped = m.skipped;
  std::vector<double> length = intrinsic::halfedge_lengths(mesh);
  intrinsic::snap_zero_lengths(length);
  m.input_length = length;
  {
    Connectivity conn = build_connectivity(mesh);
    m.ring.resize(conn.num_halfedges());
    for (Index h = 0; h < m.ring.size(); ++h) m.ring[h] = intrinsic::next_crossed(conn, skipped, length, h);
    m.input_corner_begin = std::move(conn.vertex_corner_begin);
    m.input_corners = std::move(conn.vertex_corners);
  }
  m.triangles = mesh.triangles;
  if (intrinsic_delaunay) {
    // The same flips as GSP's solver (intrinsic_delaunay.hpp): slivers become well-shaped
    // triangles of the same surface.
    detail::IntrinsicTriangulation t;
    t.triangles = std::move(m.triangles);
    t.length = std::move(length);
    t.skipped = skipped;
    t.positions = &mesh.positions;
    t.ring = std::move(m.ring);
    detail::make_intrinsic_delaunay(t, 20 * t.length.size());
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
}

WindowGeodesics::~WindowGeodesics() = default;
WindowGeodesics::WindowGeodesics(WindowGeodesics&&) noexcept = default;
WindowGeodesics& WindowGeodesics::operator=(WindowGeodesics&&) noexcept = default;

std::vector<double> WindowGeodesics::distances_from_vertex(Index source, const WindowOptions& options,
                                                           WindowStats* stats) const {
  return distances({source}, options, stats);
}

std::vector<double> WindowGeodesics::distances(const std::vector<Index>& sources, const WindowOptions& options,
                                               WindowStats* stats, std::vector<Index>* label) const {
  const Impl& mesh = *impl_;
  const auto& frame = mesh.frame;
  const std::size_t nv = mesh.num_vertices, nf = mesh.triangles.size();
  if (sources.empty()) throw std::invalid_argument("no source vertex");
  for (Index source : sources)
    if (source >= nv) throw std::invalid_argument("source vertex " + std::to_string(source) + " out of range");
  const unsigned k = options.windows;
  if (k < 1 || k > 8) throw std::invalid_argument("windows per face: 1 to 8, not " + std::to_string(k));

  std::vector<Window> win(nf * k);
  std::vector<std::uint8_t> count(nf, 0);
  std::vector<std::uint32_t> stamp(nf, 0);
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
  auto face_min = [&](Index f, const std::array<V2, kSamples>& pts) {
    Values m;
    m.fill(kInf);
    for (unsigned i = 0; i < count[f]; ++i) {
      const Values v = values(win[f * k + i], pts);
      for (int j = 0; j < kSamples; ++j) m[j] = std::min(m[j], v[j]);
    }
    return m;
  };
  // Per face: the least value over its windows at each sample, kept with the windows.
  std::vector<Values> least(nf);
  for (Values& v : least) v.fill(kInf);
  using Entry = std::tuple<double, Index, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  auto push = [&](Index f) {
    const Values& m = least[f];
    queue.emplace(*std::min_element(m.begin(), m.end()), f, ++stamp[f]);
  };
  std::size_t updates = 0;

  // Offers window w to face g; true when the face changed.
  auto offer = [&](Index g, const Window& w) {
    const auto pts = samples(g);
    Window* slots = &win[g * k];
    Values& cur = least[g];
    for (unsigned i = 0; i < count[g]; ++i) {
      Window merged;
      const int m = merge(slots[i], w, &merged);
      if (m == 0) continue;
      if (m == 1) return false;
      slots[i] = merged;
      const Values after = face_min(g, pts);
      bool better = false;
      for (int j = 0; j < kSamples; ++j) better |= after[j] < cur[j] * (1 - 1e-9);
      cur = after;
      return better ? (++updates, true) : false;
    }
    const Values nv_ = values(w, pts);
    bool better = false;
    for (int j = 0; j < kSamples; ++j) better |= nv_[j] < cur[j] * (1 - 1e-9);
    if (!better) return false;
    if (count[g] < k) {
      slots[count[g]++] = w;
      for (int j = 0; j < kSamples; ++j) cur[j] = std::min(cur[j], nv_[j]);
      return ++updates, true;
    }
    // Full: keep the k of the k + 1 windows that leave the fewest samples unreached, then the
    // lowest sum; the new one must be among them.
    std::array<Values, 9> all;
    for (unsigned i = 0; i < k; ++i) all[i] = values(slots[i], pts);
    all[k] = nv_;
    int best_drop = -1;
    std::pair<int, double> best_key{kSamples + 1, kInf};
    Values best_min{};
    for (unsigned drop = 0; drop <= k; ++drop) {
      Values m;
      m.fill(kInf);
      for (unsigned i = 0; i <= k; ++i)
        if (i != drop)
          for (int j = 0; j < kSamples; ++j) m[j] = std::min(m[j], all[i][j]);
      std::pair<int, double> key{0, 0.0};
      for (double x : m) x < kInf ? key.second += x : ++key.first;
      if (key < best_key) best_key = key, best_drop = int(drop), best_min = m;
    }
    if (best_drop == int(k)) return false;
    slots[best_drop] = w;
    cur = best_min;
    return ++updates, true;
  };

  for (std::size_t k_src = 0; k_src < sources.size(); ++k_src) {
    const Index source = sources[k_src];
    for (Index c = mesh.corner_begin[source]; c < mesh.corner_begin[source + 1]; ++c) {
      const Index corner = mesh.corners[c], f = face_of(corner);
      Window w = corner_window(frame[f][corner_of(corner)], 0.0);
      w.label = Index(k_src);
      if (offer(f, w)) push(f);
    }
  }

  while (!queue.empty()) {
    const auto [key, f, st] = queue.top();
    queue.pop();
    if (st != stamp[f]) continue;
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
          const Window& src = win[f * k + w];
          Window t = src;
          t.s = map(src.s);
          if (src.rays)
            for (int r = 0; r < 2; ++r) t.w[r] = map(src.w[r]), t.u[r] = map(src.u[r]);
          Window out[2];
          const int n = step(t, ga, gb, gp, out);
          for (int o = 0; o < n; ++o) changed |= offer(g, out[o]);
        }
        if (changed) push(g);
      }
    }
  }

  std::vector<double> dist(nv, kInf);
  std::vector<Index> from(nv, kInvalidIndex);
  std::size_t reached = 0, relaxed = 0;
  for (Index f = 0; f < nf; ++f) {
    if (count[f] > 0) ++reached;
    for (unsigned w = 0; w < count[f]; ++w)
      for (int c = 0; c < 3; ++c) {
        const Index v = mesh.triangles[f][c];
        const double d = value_at(win[f * k + w], frame[f][c]);
        if (d < dist[v]) dist[v] = d, from[v] = win[f * k + w].label;
      }
  }
  for (std::size_t k_src = 0; k_src < sources.size(); ++k_src) dist[sources[k_src]] = 0, from[sources[k_src]] = Index(k_src);
  // Along the input's edges, with GSP's own relaxation (vertex_relaxation.hpp): a value above
  // the shortest edge path (a window lost where a face kept others, a vertex the windows do
  // not reach across a vertex-only joint) takes that path, which is on the surface too.
  detail::relax_along_edges<double>(*mesh.input_triangles, mesh.input_length, 1.0, mesh.skipped,
                                    mesh.input_corner_begin, mesh.input_corners, nullptr, kInf, 0.0, dist, from,
                                    relaxed);
  if (stats) stats->window_updates = updates, stats->faces_reached = reached, stats->relaxed = relaxed;
  if (label) *label = std::move(from);
  return dist;
}

}  // namespace gsp
