// Propagation of segment sources (docs/lines.md): every face keeps the few virtual source
// segments ("waves") that are shortest at one of its sample points; a wave is carried
// over an edge by unfolding its two ends into the neighbour's frame, and bends at the edge's end
// vertex when the neighbour cannot see it through the edge. Faces are expanded in the order of
// their waves' distances (a binary heap; a face improved later is expanded again).
#include <gsp/connectivity.hpp>
#include <gsp/errors.hpp>
#include <gsp/intrinsic/bridge_vertices.hpp>
#include <gsp/intrinsic/coincident_vertices.hpp>
#include <gsp/intrinsic/corner_rules.hpp>
#include <gsp/intrinsic/edge_lengths.hpp>
#include <gsp/intrinsic/edge_relaxation.hpp>
#include <gsp/intrinsic/face_frame.hpp>
#include <gsp/intrinsic/vertex_kinds.hpp>
#include <gsp/lines/line_distances.hpp>
#include <gsp/surface_point.hpp>

#include "segment_2d.hpp"
#include "segment_bound.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <string>

namespace gsp::lines {

namespace {

using intrinsic::FaceFrame;
using intrinsic::Vec2;
using detail::segment_distance;
using intrinsic::kFlatMiss;

// Where a face compares its waves: the barycentric grid of order kGrid (corners first), so
// a wave is kept wherever it is shortest at one of them. On a plane a wave is needed exactly
// where its segment is the nearest one for some point of the face; a finer grid misses fewer of
// the thin such regions (far from many short collinear segments), at the cost of more
// comparisons per candidate.
constexpr int kGrid = 4;
constexpr int kSamples = (kGrid + 1) * (kGrid + 2) / 2;

struct SampleTable {
  std::array<std::array<double, 3>, kSamples> w;
  SampleTable() {
    int n = 3;
    w[0] = {1, 0, 0}, w[1] = {0, 1, 0}, w[2] = {0, 0, 1};
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; i + j <= kGrid; ++j) {
        const int k = kGrid - i - j;
        if (i == kGrid || j == kGrid || k == kGrid) continue;
        w[n++] = {double(i) / kGrid, double(j) / kGrid, double(k) / kGrid};
      }
  }
};
const SampleTable kSampleTable;

// A virtual source segment [a, b] in its face's canonical frame, `sigma` behind it.
// a == b is a point source (a wave that bent at a vertex).
struct Wave {
  Vec2 a, b;
  double sigma = 0;
  Index segment = 0;
};

struct Slot {
  Wave wave;
  std::array<double, kSamples> at;   // distance at the face's samples
  std::uint64_t id;
};

// At most one wave per sample survives (the shortest there); most faces hold one to three.
struct FaceWaves {
  std::vector<Slot> slot;
};

struct Entry {
  double key;
  Index face;
  std::uint64_t id;
  bool operator>(const Entry& o) const { return key > o.key; }
};

class Propagation {
 public:
  Propagation(const TriangleMesh& mesh, const LineOptions& options)
      : mesh_(mesh), options_(options), conn_(build_connectivity(mesh)) {
    const std::size_t nf = mesh.num_faces();
    frames_.resize(nf);
    faces_.resize(nf);
    const std::vector<bool> skipped_face = intrinsic::skipped_faces(mesh, conn_);   // doubled faces too
    skipped_.assign(skipped_face.begin(), skipped_face.end());   // bytes: read per candidate
    for (Index f = 0; f < Index(nf); ++f)
      if (!skipped_[f]) frames_[f] = intrinsic::face_frame(mesh, f);
    // The core's lengths and unit: tolerances in mean edges mean the same here as there.
    length_ = intrinsic::halfedge_lengths(mesh);
    intrinsic::snap_zero_lengths(length_);
    const std::vector<double>& length = length_;
    skipped_face_ = skipped_face;
    scale_ = intrinsic::mean_edge_length(length, skipped_face);
    // The core's vertex kinds (flat, saddle, convex) for the corner rules
    // (gsp/intrinsic/corner_rules.hpp): bridge and coincident vertices and the ends of
    // non-manifold edges are plain.
    const std::vector<Index> bridges = intrinsic::bridge_vertices(mesh, conn_, skipped_face);
    const intrinsic::CoincidentVertices coincident =
        intrinsic::coincident_vertices(mesh, conn_, skipped_face, length);
    kinds_ = intrinsic::vertex_kinds(mesh, conn_, skipped_face, bridges, coincident.vertices, length);
    bridge_.assign(mesh.num_vertices(), 0);
    // Bridges (gsp/intrinsic/bridge_vertices.hpp) pass their distance on as a point source.
    for (Index v : bridges) bridge_[v] = 1;
    distance_.assign(mesh.num_vertices(), std::numeric_limits<double>::infinity());
    segment_.assign(mesh.num_vertices(), kInvalidIndex);
  }

  void seed(const LineSource& src) {
    std::vector<std::uint8_t> seeded(mesh_.num_faces(), 0);
    for (std::size_t i = 0; i < src.pieces.size(); ++i) {
      const SegmentPiece& p = src.pieces[i];
      const std::string name = "line source piece " + std::to_string(i);
      const SurfacePoint start = SurfacePoint::in_face(p.face, p.start);
      if (!start.exists_in(mesh_)) throw InvalidInput(name + ": " + start.missing_from(mesh_));
      if (!(p.before >= 0 && p.after >= 0))
        throw InvalidInput(name + ": before and after must be >= 0");
      if (p.segment >= src.num_segments())
        throw InvalidInput(name + ": segment " + std::to_string(p.segment) + " does not exist");
      check_weights(p.start, name);
      check_weights(p.end, name);
      if (skipped_[p.face]) continue;   // a face without a plane: its edges carry the piece
      const FaceFrame& fr = frames_[p.face];
      if (!seeded[p.face]) ++stats_.faces_seeded, seeded[p.face] = 1;
      Vec2 a = fr.at(p.start), b = fr.at(p.end);
      const double len = intrinsic::length(b - a);
      if (len > 0 && (p.before > 0 || p.after > 0)) {   // the whole straight run (line_source.hpp)
        const Vec2 dir = (1.0 / len) * (b - a);
        a = a - p.before * dir;
        b = b + p.after * dir;
      }
      offer(p.face, {a, b, 0.0, p.segment});
    }
    stats_.segments = src.num_segments();
    stats_.pieces = src.pieces.size();
  }

  // The waves, then the core's vertex relaxation (gsp/intrinsic/edge_relaxation.hpp): values
  // lowered along the edges, and a vertex lowered by more than kPseudoSourceGain passes its
  // value on as a point source, as a bridge does, for another round. Without it a vertex
  // could end far above its edge path where the waves round it failed (a CAD pig STL with 421
  // vertices where faces only touch, its boundary as the source: 3.6x the edge path).
  void run() {
    const std::vector<Index>* from = nullptr;   // the first round looks at every edge
    std::vector<Index> changed;
    for (int round = 0;; ++round) {
      cross_bridges();
      while (!queue_.empty()) {
        const Entry e = queue_.top();
        queue_.pop();
        expand(e);
        cross_bridges();
      }
      std::size_t relaxed = 0;
      const std::vector<Index> lowered =
          intrinsic::relax_along_edges(mesh_, conn_, length_, skipped_face_, distance_, segment_, relaxed, from);
      stats_.relaxed_vertices += relaxed;
      if (lowered.empty() || round >= intrinsic::kMaxRelaxationRounds) return;
      ++stats_.relaxation_rounds;
      stats_.pseudo_sources += lowered.size();
      changed_vertices_.clear();
      recording_ = true;   // the next relaxation starts where the next round's waves lowered values
      for (Index v : lowered) bridge_pending_.push_back(v);
      cross_bridges();
      from = &changed_vertices_;
    }
  }

  LineResult result() {
    LineResult r;
    for (std::size_t v = 0; v < distance_.size(); ++v)
      if (!(distance_[v] <= options_.max_distance))
        distance_[v] = std::numeric_limits<double>::infinity(), segment_[v] = kInvalidIndex;
    for (const FaceWaves& f : faces_) {
      if (!f.slot.empty()) ++stats_.faces_reached;
      stats_.max_waves_per_face = std::max<std::uint64_t>(stats_.max_waves_per_face, f.slot.size());
    }
    r.vertex_distance = std::move(distance_);
    r.vertex_segment = std::move(segment_);
    r.stats = stats_;
    return r;
  }

 private:
  // The core's test (gsp::are_barycentric) after weights within kWeightRounding below 0 are
  // taken as 0: unlike a caller's source, a piece is usually made by polyline_source, whose
  // weights come from closest_surface_point (1 - v - w inside a face) and from splitting at
  // edges, and carry rounding just below 0 there.
  static void check_weights(std::array<double, 3> w, const std::string& name) {
    constexpr double kWeightRounding = 1e-9;
    for (double& x : w)
      if (x < 0 && x >= -kWeightRounding) x = 0;
    if (!are_barycentric(w)) throw InvalidInput(name + ": barycentric weights must be >= 0 and sum to 1");
  }

  // Keeps `w` in face f if it is clearly shorter than every wave there at one sample at least;
  // waves no longer shortest anywhere are dropped. Returns whether it was kept.
  //
  // `bent` (>= 0) names a corner the wave does not see straight (carry()): that vertex gets
  // `bent_value`, the path round the edge's end, instead of the straight unfolded distance.
  bool offer(Index f, const Wave& w, int bent = -1, double bent_value = 0) {
    ++stats_.candidates;
    const FaceFrame& fr = frames_[f];
    std::array<double, kSamples> at;
    double key = std::numeric_limits<double>::infinity();
    for (int s = 0; s < kSamples; ++s) {
      const Vec2 p = fr.at(kSampleTable.w[s]);
      at[s] = w.sigma + segment_distance(p, w.a, w.b);
      key = std::min(key, at[s]);
    }
    if (!(key <= options_.max_distance)) return false;
    FaceWaves& fw = faces_[f];
    // One wave per segment in a face: another unfolding of the same segment (round the other
    // side of a hill, or the same one rounded differently) replaces it only when it is shorter
    // over the whole face (the sum over the samples, like the core's centroid distance). Keeping
    // both would let every path's variant travel on (docs/lines.md, "The propagation").
    const int n = int(fw.slot.size());
    int same = -1;
    for (int i = 0; i < n; ++i)
      if (fw.slot[i].wave.segment == w.segment) same = i;
    if (same >= 0) {
      double sum_new = 0, sum_old = 0;
      for (int s = 0; s < kSamples; ++s) sum_new += at[s], sum_old += fw.slot[same].at[s];
      if (!(sum_new < sum_old - 1e-12 * (sum_old + kSamples * scale_))) return false;
    }
    // Among different segments: kept where it is clearly shortest at one sample at least. Only
    // a clear improvement counts: one lost in rounding would bounce between faces forever.
    std::array<int, kSamples> winner;
    bool useful = false;
    for (int s = 0; s < kSamples; ++s) {
      int best = -1;
      for (int i = 0; i < n; ++i)
        if (i != same && (best < 0 || fw.slot[i].at[s] < fw.slot[best].at[s])) best = i;
      const bool better = best < 0 || at[s] < fw.slot[best].at[s] - 1e-12 * (fw.slot[best].at[s] + scale_);
      winner[s] = better ? kSamples : best;
      useful = useful || better;
    }
    if (!useful) return false;
    std::size_t kept = 0;
    for (int i = 0; i < n; ++i)
      if (i != same && std::find(winner.begin(), winner.end(), i) != winner.end()) fw.slot[kept++] = fw.slot[i];
    fw.slot.resize(kept);
    const std::uint64_t id = ++next_id_;
    fw.slot.push_back(Slot{w, at, id});
    ++stats_.waves_accepted;
    const Triangle& t = mesh_.triangles[f];
    for (int c = 0; c < 3; ++c) {
      const double d = c == bent ? bent_value : at[c];
      if (!(d < distance_[t[c]])) continue;
      distance_[t[c]] = d, segment_[t[c]] = w.segment;
      if (recording_) changed_vertices_.push_back(t[c]);
      if (bridge_[t[c]]) bridge_pending_.push_back(t[c]);
    }
    queue_.push({key, f, id});
    return true;
  }

  // A point source at every bridge vertex whose distance dropped, offered to all its faces.
  void cross_bridges() {
    while (!bridge_pending_.empty()) {
      const Index v = bridge_pending_.back();
      bridge_pending_.pop_back();
      for (Index k = conn_.vertex_corner_begin[v]; k < conn_.vertex_corner_begin[v + 1]; ++k) {
        const Index f = face_of(conn_.vertex_corners[k]);
        if (skipped_[f]) continue;
        const Vec2 p = frames_[f].corner[corner_of(conn_.vertex_corners[k])];
        offer(f, {p, p, distance_[v], segment_[v]});
      }
    }
  }

  void expand(const Entry& e) {
    const FaceWaves& fw = faces_[e.face];
    std::size_t i = 0;
    while (i < fw.slot.size() && fw.slot[i].id != e.id) ++i;
    if (i == fw.slot.size()) {
      ++stats_.stale_skipped;
      return;
    }
    ++stats_.expansions;
    const Wave w = fw.slot[i].wave;   // a copy: offering below may rewrite this face's slots
    for (int j = 0; j < 3; ++j) {
      const Index h = Index(3 * e.face + j);
      for (Index g = conn_.radial_next[h]; g != h; g = conn_.radial_next[g])
        if (!skipped_[face_of(g)]) carry(w, e.face, h, g);
    }
  }

  // Carries wave w of face u over halfedge h into the face of g (a halfedge on the same edge).
  void carry(const Wave& w, Index u, Index h, Index g) {
    const FaceFrame& fu = frames_[u];
    const int j = int(corner_of(h));
    const double e1 = fu.len[j];
    // Into g's edge frame (its face on +y, u's on -y). x is measured from the other end
    // unless the two faces disagree in orientation and walk the edge the same way.
    const bool same_dir = from_vertex(mesh_, h) == from_vertex(mesh_, g);
    auto unfold = [&](Vec2 p) {
      const Vec2 q = fu.to_edge(j, p);
      return Vec2{same_dir ? q.x : e1 - q.x, -q.y};
    };
    const Vec2 a = unfold(w.a), b = unfold(w.b);
    const Index t = face_of(g);
    const FaceFrame& ft = frames_[t];
    const int k = int(corner_of(g));
    const Vec2 A{0, 0}, B{e1, 0}, P = ft.to_edge(k, ft.corner[(k + 2) % 3]);

    // The probe Q between the opposite corner and the centroid (the core's heuristic): the
    // wave is visible when the straight line from Q to the nearest point of the segment
    // crosses the edge.
    const Vec2 C = (1.0 / 3.0) * (A + B + P);
    const double max_e = std::max({ft.len[0], ft.len[1], ft.len[2]});
    const double min_e = std::min({ft.len[0], ft.len[1], ft.len[2]});
    const double lambda = e1 > 0 ? options_.heuristic.blend(e1, max_e, min_e, P.y) : 1.0;
    const Vec2 Q = P + lambda * (C - P);
    const Vec2 N = detail::nearest_on_segment(Q, a, b);
    const double eps = 1e-9 * scale_;
    // Where the line from R to the wave's nearest point NR (on u's side) crosses the edge's
    // line: 0 within AB (or no crossing), 1 before A, 2 beyond B; `beyond` gets how far past
    // that end. The probe Q, the corner rules' probes and the opposite corner P all use it.
    auto crossing_through = [&](Vec2 R, Vec2 NR, double* beyond = nullptr) {
      const double d = R.y - NR.y;
      if (!(d > 0)) return 0;
      const double x = R.x + (NR.x - R.x) * (R.y / d);
      const int side = x < -eps ? 1 : (x > e1 + eps ? 2 : 0);
      if (beyond) *beyond = side == 1 ? -x : x - e1;
      return side;
    };
    int kind = 0;   // 0: straight on, 1: bend at A, 2: bend at B
    double miss = 0;  // how far beyond the bend's end the probe's line crosses the edge's line
    const bool same_side = N.y > eps;
    if (!same_side) {
      kind = crossing_through(Q, N, &miss);
    } else {
      // The nearest point lies on t's side: the segment was carried round a vertex. Bend at
      // the end of the edge that gives the shorter path to Q — even at a flat vertex, as the
      // core does: carried on, a wave can circle a vertex that is flat only to 1e-6 and come
      // back a little shorter every round (docs/lines.md, "Cost").
      const double via_a = segment_distance(A, a, b) + intrinsic::length(Q - A);
      const double via_b = segment_distance(B, a, b) + intrinsic::length(Q - B);
      kind = via_a <= via_b ? 1 : 2;
    }
    // The corner rules, as in the core: a bend at a flat, convex or saddle end reconsidered,
    // a straight crossing checked at saddle ends. `crossing(lambda)` is the same test from
    // the probe at lambda (0: P, 1: the centroid); a wave already reaching t's side is seen.
    const Triangle& tt = mesh_.triangles[t];
    const std::uint8_t kind_a = kinds_[tt[k]], kind_b = kinds_[tt[(k + 1) % 3]];
    if (!same_side) {
      auto crossing = [&](double at) {
        const Vec2 R = P + at * (C - P);
        const Vec2 NR = detail::nearest_on_segment(R, a, b);
        return NR.y > eps ? 0 : crossing_through(R, NR);
      };
      if (kind != 0)
        // The kernel runs on the mesh's own triangles (no intrinsic flips): rule 7's stricter probe.
        kind = intrinsic::reconsider_bend(kind, kind == 1 ? kind_a : kind_b, intrinsic::kSaddleLooseLambdaInputFaces,
                                          [&] { return miss <= kFlatMiss * scale_; }, crossing);
      if (kind == 0 && e1 > 0)
        kind = intrinsic::straight_past_saddles(kind_a == intrinsic::kSaddleVertex, kind_b == intrinsic::kSaddleVertex,
                                                crossing);
    }

    Wave n;
    n.segment = w.segment;
    int bent = -1;
    double bent_value = 0;
    if (kind == 0) {
      n.a = ft.from_edge(k, a), n.b = ft.from_edge(k, b), n.sigma = w.sigma;
      // The probe sees the wave, but the opposite corner P may not (the wave passes the edge's
      // end on its way to P): on a curved surface the straight unfolded distance to P would
      // cut across the missing angle round that vertex and come out too short.
      const Vec2 NP = detail::nearest_on_segment(P, a, b);
      int side = 0;
      if (NP.y > eps) {
        const double via_a = segment_distance(A, a, b) + intrinsic::length(P - A);
        const double via_b = segment_distance(B, a, b) + intrinsic::length(P - B);
        side = via_a <= via_b ? 1 : 2;
      } else {
        side = crossing_through(P, NP);
      }
      if (side == 1 && kind_a == intrinsic::kFlatVertex) side = 0;
      if (side == 2 && kind_b == intrinsic::kFlatVertex) side = 0;
      if (side != 0) {
        const Vec2 corner = side == 1 ? A : B;
        bent = (k + 2) % 3;
        bent_value = w.sigma + segment_distance(corner, a, b) + intrinsic::length(P - corner);
      }
    } else {
      const Vec2 corner = kind == 1 ? A : B;
      n.a = n.b = ft.corner[kind == 1 ? k : (k + 1) % 3];
      n.sigma = w.sigma + segment_distance(corner, a, b);
    }
    if (offer(t, n, bent, bent_value) && kind != 0) ++stats_.bends;
  }

  const TriangleMesh& mesh_;
  LineOptions options_;
  Connectivity conn_;
  std::vector<FaceFrame> frames_;
  std::vector<std::uint8_t> skipped_, kinds_, bridge_;
  std::vector<bool> skipped_face_;   // the same as skipped_, as the relaxation takes it
  std::vector<double> length_;       // per halfedge, snapped (the relaxation's edges)
  std::vector<Index> bridge_pending_;
  std::vector<Index> changed_vertices_;   // lowered by the waves since the last relaxation
  bool recording_ = false;                 // from the second round on (the first relaxes every edge)
  std::vector<FaceWaves> faces_;
  std::vector<double> distance_;
  std::vector<Index> segment_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
  std::uint64_t next_id_ = 0;
  double scale_ = 1;
  LineStats stats_;
};

}  // namespace

LineResult line_distances(const TriangleMesh& mesh, const LineSource& source, const LineOptions& options) {
  validate(mesh);
  Propagation p(mesh, options);
  p.seed(source);
  p.run();
  LineResult r = p.result();
  if (options.straight_line_bound)
    r.stats.raised_to_line = raise_to_segments(mesh, source, r.vertex_distance, r.vertex_segment);
  return r;
}

}  // namespace gsp::lines
