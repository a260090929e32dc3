#include <gsp/layout.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gsp {

namespace {

// Runs of consecutive faces, not a stride: a stride can alias with the order's own period (the
// 4 children of a subdivided face). Reading the triangles in order keeps the estimate cheap on
// a scattered file, where gathering the edges (the exact measure) cost 10% of the run it was to
// save.
double sampled_log_gap(const TriangleMesh& mesh) {
  const std::size_t nf = mesh.num_faces(), runs = 64, run = 200000 / runs;
  double sum = 0;
  std::size_t n = 0;
  auto add = [&](std::size_t f) {
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      sum += std::log2(1.0 + double(a > b ? a - b : b - a));
      ++n;
    }
  };
  if (nf <= runs * run) {
    for (std::size_t f = 0; f < nf; ++f) add(f);
  } else {
    for (std::size_t r = 0; r < runs; ++r)
      for (std::size_t f = r * (nf / runs), end = f + run; f < end; ++f) add(f);
  }
  return n ? sum / double(n) : 0.0;
}

// How far apart in the face order the faces around one vertex lie: mean log2(1 + last - first
// face index) over a sample of vertices (every 2^k-th, at most about 65,536 of them), in one
// read of the triangles. Consecutive faces can share a vertex and still leave each face's
// neighbours far away: the four children of a subdivided face stored in four blocks (libigl's
// upsample, a split written block by block) have coherent vertices and runs of faces, but the
// faces round a vertex are a quarter of the file apart.
double sampled_face_spread(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  unsigned shift = 0;
  while ((nv >> shift) > 65536) ++shift;
  const std::size_t mask = (std::size_t(1) << shift) - 1, slots = (nv >> shift) + 1;
  std::vector<Index> first(slots, kInvalidIndex), last(slots, 0);
  for (std::size_t f = 0; f < nf; ++f)
    for (Index v : mesh.triangles[f]) {
      if ((v & mask) != 0 || v >= nv) continue;
      const std::size_t s = v >> shift;
      if (first[s] == kInvalidIndex) first[s] = Index(f);
      last[s] = Index(f);
    }
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t s = 0; s < slots; ++s)
    if (first[s] != kInvalidIndex) sum += std::log2(1.0 + double(last[s] - first[s])), ++n;
  return n ? sum / double(n) : 0.0;
}

}  // namespace

OrderCoherence order_coherence(const TriangleMesh& mesh) {
  OrderCoherence c;
  c.file_log_gap = sampled_log_gap(mesh);
  c.random_log_gap = std::log2(double(std::max<std::size_t>(mesh.num_vertices(), 4))) - 2;
  c.coherent = c.random_log_gap - c.file_log_gap >= kCoherentLogGap;
  c.face_spread = sampled_face_spread(mesh);
  // A vertex's k faces at random among F span about F (k - 1) / (k + 1): log2 F - 0.5 for six.
  c.random_face_spread = std::log2(double(std::max<std::size_t>(mesh.num_faces(), 4))) - 1;
  c.faces_coherent = c.random_face_spread - c.face_spread >= kCoherentLogGap;
  c.sort_faces = c.coherent && !c.faces_coherent && mesh.num_faces() >= kSortFacesFrom;
  return c;
}

}  // namespace gsp
