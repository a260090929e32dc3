#pragma once
// Sharp features of a triangle mesh: crease edges by dihedral angle (MeshLab's and CGAL's
// `featuredeg`), boundary and non-manifold edges, the corners where feature curves meet, end
// or turn sharply, and the curves between corners as vertex chains. What a remesh of a CAD
// part must keep, and where its distance to the input is measured (docs/cvt.md).
//
//   gsp::cvt::Features f = gsp::cvt::detect_features(mesh, {});
//   f.edges, f.corners, f.curves[i] (vertex chain; closed when front() == back())
#include <gsp/mesh.hpp>

#include <array>
#include <vector>

namespace gsp::cvt {

struct FeatureOptions {
  // An edge between two faces is a crease when their normals differ by more than this many
  // degrees (0 = flat).
  double angle = 40.0;
  bool boundary = true;   // boundary edges are feature edges
  // A vertex on exactly two feature edges is a corner when the curve turns there by more than
  // this many degrees (0 = straight on).
  double corner_turn = 50.0;
};

struct Features {
  std::vector<std::array<Index, 2>> edges;   // each undirected feature edge once, smaller index first
  std::vector<Index> corners;                // ascending
  std::vector<std::vector<Index>> curves;    // from corner to corner; a closed curve without corner repeats its first vertex
};

Features detect_features(const TriangleMesh& mesh, const FeatureOptions& options = {});

}  // namespace gsp::cvt
