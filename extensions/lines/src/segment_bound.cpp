#include "segment_bound.hpp"

#include <gsp/surface_point.hpp>

#include <algorithm>
#include <limits>

namespace gsp::lines {

namespace {

struct Piece3 {
  Vec3 a, b;
  Index segment;
};

double segment_distance(Vec3 x, const Piece3& p) {
  const Vec3 ab = p.b - p.a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(x - p.a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(x, p.a + t * ab);
}

}  // namespace

std::size_t raise_to_segments(const TriangleMesh& mesh, const LineSource& source, std::vector<double>& distance,
                              std::vector<Index>& segment) {
  std::vector<Piece3> pieces;
  pieces.reserve(source.pieces.size());
  for (const SegmentPiece& p : source.pieces)
    pieces.push_back({SurfacePoint::in_face(p.face, p.start).position(mesh),
                      SurfacePoint::in_face(p.face, p.end).position(mesh), p.segment});
  if (pieces.empty()) return 0;
  // Pieces by segment (CSR), so a vertex is first checked against its own segment's pieces.
  std::vector<Index> begin(source.num_segments() + 1, 0), order(pieces.size());
  for (const Piece3& p : pieces) ++begin[p.segment + 1];
  for (std::size_t s = 0; s < source.num_segments(); ++s) begin[s + 1] += begin[s];
  std::vector<Index> fill(begin.begin(), begin.end() - 1);
  for (Index i = 0; i < pieces.size(); ++i) order[fill[pieces[i].segment]++] = i;

  std::size_t raised = 0;
  for (std::size_t v = 0; v < distance.size(); ++v) {
    if (!(distance[v] < std::numeric_limits<double>::infinity())) continue;
    const Vec3 x = mesh.positions[v];
    const Index s = segment[v];
    if (s < source.num_segments()) {
      double own = std::numeric_limits<double>::infinity();
      for (Index k = begin[s]; k < begin[s + 1]; ++k) own = std::min(own, segment_distance(x, pieces[order[k]]));
      if (distance[v] >= own) continue;
    }
    double bound = std::numeric_limits<double>::infinity();
    Index nearest = s;
    for (const Piece3& p : pieces) {
      const double b = segment_distance(x, p);
      if (b < bound) bound = b, nearest = p.segment;
    }
    if (distance[v] >= bound) continue;
    raised += distance[v] < bound * (1 - 1e-6);
    distance[v] = bound;
    segment[v] = nearest;
  }
  return raised;
}

}  // namespace gsp::lines
