#pragma once
// Intrinsic Delaunay flips (internal): edge flips that keep the surface's metric exactly (the
// two triangles are unfolded into the plane and the other diagonal measured), until every
// flippable edge is Delaunay. Slivers and fans become well-shaped triangles on the same
// surface with the same vertices, so one virtual source per face fits them far better.
#include <gsp/types.hpp>

#include <vector>

namespace gsp::detail {

struct IntrinsicTriangulation {
  std::vector<Triangle> triangles;   // corner vertices
  std::vector<double> length;        // per halfedge 3f+i: |corner i -> corner i+1|
  std::vector<Index> ring;           // per halfedge: next halfedge on its edge (plain index)
  std::vector<bool> skipped;         // faces left out of the propagation
};

// Flips in place; returns the number of flips. Only edges with exactly two consistently
// oriented, non-skipped faces and two distinct opposite vertices are flipped.
std::size_t make_intrinsic_delaunay(IntrinsicTriangulation& t, std::size_t max_flips);

}  // namespace gsp::detail
