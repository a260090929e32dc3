#pragma once
// Closest points on a triangle mesh for many queries: Embree's BVH point query (rtcPointQuery)
// narrows the candidates, the distance to each candidate triangle is computed in double
// precision by gsp::closest_point_on_triangle. Thread-safe queries after construction.
#include <gsp/closest_point.hpp>
#include <gsp/mesh.hpp>

#include <memory>

namespace gsp::cvt {

class ClosestPointIndex {
 public:
  // Keeps a reference to `mesh`. Faces that repeat a vertex are left out; throws InvalidInput
  // when no face is left, gsp::Error when Embree fails.
  explicit ClosestPointIndex(const TriangleMesh& mesh);
  ~ClosestPointIndex();
  ClosestPointIndex(const ClosestPointIndex&) = delete;
  ClosestPointIndex& operator=(const ClosestPointIndex&) = delete;

  ClosestPoint closest(Vec3 p) const;
  // The same answer, found faster when face `hint` (a face of the mesh, or kInvalidIndex) is
  // near p: the search starts bounded by the hint's distance instead of unbounded. Searches
  // of points close together (a vertex's candidate positions) pass the last answer's face.
  ClosestPoint closest(Vec3 p, Index hint) const;
  // The closest point to p on face f alone, computed as the searches compute it: a caller
  // whose faces changed since the index was built (edge flips, positions kept) takes the
  // nearer of closest(p) and these for the changed faces, with ties to the lower face, and
  // gets what an index built anew would answer (the changed faces' boxes are stale, the
  // others' are not).
  ClosestPoint on_face(Index f, Vec3 p) const;
  // Whether a triangle lies within distance r of p (closest(p).distance <= r, decided in the
  // same double precision), found faster: the search is bounded by r and stops at the first.
  bool within(Vec3 p, double r) const;
  // The same, trying face `hint` first (kInvalidIndex: none); `hint` gets the face that was
  // found within r, so a caller asking again about a nearby point asks that face first.
  bool within(Vec3 p, double r, Index& hint) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gsp::cvt
