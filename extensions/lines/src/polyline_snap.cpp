// 3D polylines laid onto the surface: the closest-point projection of each segment, cut into
// straight pieces at the faces it crosses (method in line_source.hpp and docs/lines.md).
#include <gsp/closest_point.hpp>
#include <gsp/errors.hpp>
#include <gsp/intrinsic/face_frame.hpp>
#include <gsp/lines/line_source.hpp>

#include <string>

namespace gsp::lines {

namespace {

using intrinsic::FaceFrame;
using intrinsic::Vec2;

// Halving a 3D segment this often makes its halves ~1e-9 of its length: if their closest
// points still lie in faces that touch nowhere, the projection jumps (a gap, a far point).
constexpr int kMaxDepth = 30;
constexpr double kZeroWeight = 1e-12;

// A polyline point snapped onto the surface: the face point closest to it.
SurfacePoint snap(const TriangleMesh& mesh, Vec3 p, double& max_distance) {
  const ClosestPoint s = closest_surface_point(mesh, p);
  max_distance = std::max(max_distance, s.distance);
  return s.point;
}

// The same surface point as weights of face g's corners, when it lies on g (on a shared edge
// or vertex): every corner it leans on must be one of g's.
bool express_in(const TriangleMesh& mesh, const SurfacePoint& s, Index g, std::array<double, 3>& out) {
  out = {0, 0, 0};
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    if (s.barycentric[i] <= kZeroWeight) continue;
    int k = 0;
    while (k < 3 && mesh.triangles[g][k] != mesh.triangles[s.element][i]) ++k;
    if (k == 3) return false;
    out[k] += s.barycentric[i];
    sum += s.barycentric[i];
  }
  if (!(sum > 0)) return false;
  for (double& x : out) x /= sum;
  return true;
}

int shared_vertices(const Triangle& a, const Triangle& b, Index* first = nullptr) {
  int n = 0;
  for (Index x : a)
    for (Index y : b)
      if (x == y) {
        if (first && n == 0) *first = x;
        ++n;
      }
  return n;
}

int corner_with(const Triangle& t, Index v) { return t[0] == v ? 0 : (t[1] == v ? 1 : 2); }

std::array<double, 3> unit(int corner) {
  std::array<double, 3> w{0, 0, 0};
  w[corner] = 1;
  return w;
}

// The halfedge of face a on the edge it shares with face b (both ends are b's corners).
int shared_halfedge(const Triangle& a, const Triangle& b) {
  auto has = [&](Index v) { return b[0] == v || b[1] == v || b[2] == v; };
  int j = 0;
  while (j < 2 && !(has(a[j]) && has(a[(j + 1) % 3]))) ++j;
  return j;
}

// Face g's corners in face f's canonical frame, g unfolded over the edge they share.
std::array<Vec2, 3> unfold_neighbour(const TriangleMesh& mesh, const FaceFrame& ff, Index f, Index g) {
  const Triangle &fs = mesh.triangles[f], &ft = mesh.triangles[g];
  const int j = shared_halfedge(fs, ft);
  const Index va = fs[j], vb = fs[(j + 1) % 3];
  const double e = ff.len[j];
  std::array<Vec2, 3> out;
  for (int k = 0; k < 3; ++k) {
    Vec2 p;
    if (ft[k] == va) p = {0, 0};
    else if (ft[k] == vb) p = {e, 0};
    else {   // on the other side of the edge (-y in f's edge frame)
      const double da = distance(mesh.positions[ft[k]], mesh.positions[va]);
      const double db = distance(mesh.positions[ft[k]], mesh.positions[vb]);
      const double x = e > 0 ? (e * e + da * da - db * db) / (2 * e) : 0.0;
      p = {x, -std::sqrt(std::max(0.0, da * da - x * x))};
    }
    out[k] = ff.from_edge(j, p);
  }
  return out;
}

// Splits the pieces [first, end) of one segment into straight runs: q continues p when both
// lie in one face, or in faces sharing an edge, along one line of their unfolding. Each piece
// then learns how far its run reaches before and after it (SegmentPiece::before, after).
void mark_runs(const TriangleMesh& mesh, std::vector<SegmentPiece>& pieces, std::size_t first) {
  const std::size_t end = pieces.size();
  std::vector<double> len(end - first);
  std::vector<Vec2> dir(end - first);
  for (std::size_t i = first; i < end; ++i) {
    const FaceFrame fr = intrinsic::face_frame(mesh, pieces[i].face);
    const Vec2 d = fr.at(pieces[i].end) - fr.at(pieces[i].start);
    len[i - first] = intrinsic::length(d);
    dir[i - first] = len[i - first] > 0 ? (1.0 / len[i - first]) * d : Vec2{0, 0};
  }
  auto continues = [&](std::size_t i) {   // does piece i+1 continue piece i straight?
    const SegmentPiece &p = pieces[i], &q = pieces[i + 1];
    if (!(len[i - first] > 0) || !(len[i + 1 - first] > 0)) return false;
    Vec2 dq = dir[i + 1 - first];
    if (q.face != p.face) {
      const Triangle &a = mesh.triangles[p.face], &b = mesh.triangles[q.face];
      if (shared_vertices(a, b) < 2) return false;
      const FaceFrame ff = intrinsic::face_frame(mesh, p.face);
      const std::array<Vec2, 3> g = unfold_neighbour(mesh, ff, p.face, q.face);
      auto at = [&](const std::array<double, 3>& w) { return w[0] * g[0] + w[1] * g[1] + w[2] * g[2]; };
      const Vec2 d = at(q.end) - at(q.start);
      dq = (1.0 / intrinsic::length(d)) * d;
    }
    const Vec2 dp = dir[i - first];
    return std::abs(dp.x * dq.y - dp.y * dq.x) < 1e-8 && intrinsic::dot(dp, dq) > 0;
  };
  std::size_t run = first;
  for (std::size_t i = first; i < end; ++i) {
    if (i + 1 < end && continues(i)) continue;
    // pieces [run, i] form one run
    double total = 0;
    for (std::size_t k = run; k <= i; ++k) total += len[k - first];
    double done = 0;
    for (std::size_t k = run; k <= i; ++k) {
      pieces[k].before = done;
      done += len[k - first];
      pieces[k].after = std::max(0.0, total - done);
    }
    run = i + 1;
  }
}

class Layer {
 public:
  Layer(const TriangleMesh& mesh, LineSource& out) : mesh_(mesh), out_(out) {}

  // Joins s (closest point of a) to t (closest point of b), a and b being 3D points of segment
  // `segment`.
  void join(const SurfacePoint& s, const SurfacePoint& t, Vec3 a, Vec3 b, Index segment, int depth) {
    std::array<double, 3> w;
    if (s.element == t.element) return piece(s.element, s.barycentric, t.barycentric, segment);
    if (express_in(mesh_, s, t.element, w)) return piece(t.element, w, t.barycentric, segment);
    if (express_in(mesh_, t, s.element, w)) return piece(s.element, s.barycentric, w, segment);
    const Triangle &fs = mesh_.triangles[s.element], &ft = mesh_.triangles[t.element];
    Index common = kInvalidIndex;
    const int shared = shared_vertices(fs, ft, &common);
    // Faces sharing an edge: straight across it, unless the straight line misses the edge
    // (it runs through a third face around one of the edge's ends): then halve.
    if (shared >= 2 && (across_edge(s, t, segment, depth >= kMaxDepth))) return;
    if (depth < kMaxDepth) {
      const Vec3 m = 0.5 * (a + b);
      const SurfacePoint sm = snap(mesh_, m, out_.max_snap_distance);
      join(s, sm, a, m, segment, depth + 1);
      join(sm, t, m, b, segment, depth + 1);
      return;
    }
    if (shared == 1) {   // faces touching at one vertex: go through it
      piece(s.element, s.barycentric, unit(corner_with(fs, common)), segment);
      piece(t.element, unit(corner_with(ft, common)), t.barycentric, segment);
      return;
    }
    const Vec3 p = mesh_.positions[fs[0]];
    throw InvalidInput("polyline segment " + std::to_string(segment) +
                       ": its closest points on the surface jump near (" + std::to_string(p.x) + ", " +
                       std::to_string(p.y) + ", " + std::to_string(p.z) +
                       "); does the polyline run far from the surface or across a gap?");
  }

 private:
  void piece(Index f, const std::array<double, 3>& a, const std::array<double, 3>& b, Index segment) {
    out_.pieces.push_back({f, a, b, segment});
  }

  // s and t in faces sharing an edge: the straight line between them in the unfolding of the
  // two faces crosses the edge at one point (clamped to the edge when it would miss it).
  // Returns false (and adds nothing) when the line misses the edge, unless `clamp`.
  bool across_edge(const SurfacePoint& s, const SurfacePoint& t, Index segment, bool clamp) {
    const Triangle &fs = mesh_.triangles[s.element], &ft = mesh_.triangles[t.element];
    const FaceFrame ff = intrinsic::face_frame(mesh_, s.element);
    const std::array<Vec2, 3> g = unfold_neighbour(mesh_, ff, s.element, t.element);
    const int j = shared_halfedge(fs, ft);
    const Vec2 se = ff.to_edge(j, ff.at(s.barycentric));
    const Vec2 te = ff.to_edge(j, t.barycentric[0] * g[0] + t.barycentric[1] * g[1] + t.barycentric[2] * g[2]);
    const double e = ff.len[j];
    double x = 0.5 * (se.x + te.x);
    if (se.y - te.y > 0) x = se.x + (te.x - se.x) * (se.y / (se.y - te.y));
    const double raw = e > 0 ? x / e : 0.0;
    if (!clamp && !(raw >= -1e-9 && raw <= 1 + 1e-9)) return false;
    const double tau = std::clamp(raw, 0.0, 1.0);
    const Index va = fs[j], vb = fs[(j + 1) % 3];
    std::array<double, 3> cs{0, 0, 0}, ct{0, 0, 0};
    cs[j] = 1 - tau, cs[(j + 1) % 3] = tau;
    ct[corner_with(ft, va)] = 1 - tau, ct[corner_with(ft, vb)] = tau;
    piece(s.element, s.barycentric, cs, segment);
    piece(t.element, ct, t.barycentric, segment);
    return true;
  }

  const TriangleMesh& mesh_;
  LineSource& out_;
};

}  // namespace

LineSource polyline_source(const TriangleMesh& mesh, const std::vector<Polyline>& polylines) {
  validate(mesh);
  LineSource src;
  Layer layer(mesh, src);
  for (std::size_t k = 0; k < polylines.size(); ++k) {
    const Polyline& line = polylines[k];
    const std::string name = "polyline " + std::to_string(k);
    if (line.size() < 2) throw InvalidInput(name + ": needs at least two points, has " + std::to_string(line.size()));
    for (std::size_t i = 0; i < line.size(); ++i)
      if (!is_finite(line[i])) throw InvalidInput(name + ": point " + std::to_string(i) + " is not finite");
    std::vector<SurfacePoint> snapped;
    std::vector<Vec3> on_surface;
    for (const Vec3& p : line) {
      snapped.push_back(snap(mesh, p, src.max_snap_distance));
      on_surface.push_back(snapped.back().position(mesh));
    }
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const Index segment = Index(src.segments.size());
      const std::size_t first = src.pieces.size();
      layer.join(snapped[i], snapped[i + 1], line[i], line[i + 1], segment, 0);
      mark_runs(mesh, src.pieces, first);
      src.segments.push_back({on_surface[i], on_surface[i + 1]});
    }
  }
  return src;
}

}  // namespace gsp::lines
