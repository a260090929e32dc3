#pragma once
// The running distance-to-nearest-sample field of Poisson-disk sampling: per vertex the
// minimum over the bounded runs so far, and per face the virtual sources (paper Fig. 7c) of
// every run that reached it closely enough, so the distance at any point of a face is
// min over them of sigma + |p - S|. A linked list per face in one pool: faces far from
// every sample cost one index, and a face is near only a bounded number of samples that are
// r apart. A face larger than r holds more (a CAD part's flat faces, a single triangle: all
// of them); past kDense its sources and samples go into cubes of side r (FaceCells) and
// only those around a point are read.
#include "face_cells.hpp"

#include <gsp/geodesics.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace gsp::sampling::detail {

// The core's paths through a face's corners (gsp::corner_paths, geodesics.hpp).
using gsp::corner_paths;

// The faces round each vertex (CSR: those of v are faces[begin[v] .. begin[v + 1])).
struct VertexFaces {
  std::vector<Index> begin, faces;
  explicit VertexFaces(const TriangleMesh& mesh);
};

class CoverageField {
 public:
  // `referenced` marks the vertices used by a face; only those count as uncovered.
  CoverageField(const TriangleMesh& mesh, const std::vector<bool>& referenced, double radius);

  // True when the run (from a candidate) reaches no earlier sample closer than `radius`. GSP's distance from a
  // to b and from b to a can differ by several percent on coarse meshes (one virtual source
  // per face), so the candidate test checks both directions: the field at the candidate
  // (earlier runs) before its run, this after it.
  bool clear_of_samples(const LocalField& run) const;
  // Registers a sample at (face, barycentric) for clear_of_samples.
  void add_sample(Index face, const std::array<double, 3>& barycentric);

  // Merges one run: vertex minimum everywhere it reached; face virtual sources of the faces
  // that can hold a point within r (centroid distance minus the face's centroid radius).
  // Cost: the run's neighbourhood (compute_local lists only what it reached).
  void merge(const LocalField& run);

  // Distance from the point p of face f to the nearest sample so far, exact where it is
  // below r; at or above r it may be any value at or above r (+inf if none near). The lower
  // of the face's virtual sources and its corners' values plus the straight segment to p
  // (corner_paths): each is the length of a path, and on a long sliver the one virtual source
  // can be a bend that is right for one end and far too long at the other.
  double distance_at(Index face, Vec3 p) const {
    double best = corner_paths(mesh_, face, p, vertex_);
    auto take = [&](std::int32_t e) {
      const double d = pool_[e].sigma + distance(p, pool_[e].position);
      if (d < best) best = d;
    };
    if (source_count_[face] > kDense)
      source_cells_.near(face, p, take);
    else
      for (std::int32_t e = head_[face]; e >= 0; e = pool_[e].next) take(e);
    return best;
  }

  const std::vector<double>& vertex() const { return vertex_; }
  std::size_t uncovered() const { return uncovered_; }        // referenced vertices at >= r
  std::size_t referenced_count() const { return referenced_count_; }

 private:
  struct Entry {
    Vec3 position;
    double sigma;
    std::int32_t next;
  };
  // A face can hold a point within r of the run's source.
  bool near(const LocalField& run, std::size_t k) const {
    return run.face_distance[k] - centroid_radius_[run.faces[k]] < radius_;
  }
  static constexpr std::uint32_t kDense = 16;   // items a face keeps in its list
  void add_source(Index face, Vec3 position, double sigma);
  std::vector<double> vertex_;
  // clear_of_samples' scratch: the run's vertex distances by vertex (+inf elsewhere), reset
  // after each run.
  mutable std::vector<double> run_vertex_;
  VertexFaces round_;
  std::vector<double> centroid_radius_;   // per face: largest centroid-to-corner distance
  std::vector<std::int32_t> head_;
  std::vector<Entry> pool_;
  std::vector<std::int32_t> sample_head_;   // per face: first sample in it, -1 if none
  std::vector<std::int32_t> sample_next_;   // per sample: the next in its face's list
  std::vector<Vec3> sample_position_;
  // Per face: items so far; past kDense they are in the cubes (and the lists are not read).
  std::vector<std::uint32_t> source_count_, sample_count_;
  FaceCells source_cells_, sample_cells_;
  const TriangleMesh& mesh_;
  const std::vector<bool>& referenced_;
  double radius_;
  std::size_t uncovered_ = 0, referenced_count_ = 0;
};

}  // namespace gsp::sampling::detail
