#pragma once
// What gsp::WindowGeodesics prepares (its faces, frames and rings) and what a computed
// gsp::WindowField holds (every face's windows), shared by the propagation
// (window_geodesics.cpp) and the field's queries (window_field.cpp).
#include <gsp/window_geodesics.hpp>

#include "window_step.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace gsp {

struct WindowGeodesics::Impl {
  std::size_t num_vertices = 0;
  const std::vector<Vec3>* positions = nullptr;
  bool intrinsic = false;   // the faces are the intrinsic Delaunay flip, not the input's
  double mean_edge = 1;
  // The windows' geometry is held times `unit`, a power of two that brings the mean edge into
  // [1/2, 1): exact (a power of two rounds nothing), and the windows' tolerances, written for
  // models near unit size (a source within 1e-9 (1 + sigma) of another is the same one), then
  // mean the same at every scale. Distances out are divided by it, points in and out scaled.
  // (The CGAL pig scaled by 1e-7 gave a path 2.2% longer than its field.)
  double unit = 1;
  // The input's edges for the final relaxation (vertex_relaxation.hpp): its triangles (the
  // caller keeps the mesh), their halfedge lengths, skipped faces and vertex -> corner lists.
  const std::vector<Triangle>* input_triangles = nullptr;
  std::vector<double> input_length;
  std::vector<bool> skipped;
  std::vector<Index> input_corner_begin, input_corners;
  std::vector<Triangle> triangles;        // the propagation's faces (intrinsic Delaunay or input)
  std::vector<Index> ring;                // per halfedge: the next face's halfedge on its edge
  std::vector<std::array<detail::windows::V2, 3>> frame;   // per face: its corners in its own plane
  std::vector<Index> corner_begin, corners;   // vertex -> corners 3 f + i, CSR
  // Per corner (the order of `corners`): the fan of its vertex it belongs to (faces joined
  // over the propagation's edges around the vertex), numbered from 0 per vertex; and the
  // vertices with more than one fan (joints: faces that meet there only at the vertex), where
  // windows cannot cross an edge and a value at the vertex goes on as a corner window instead.
  std::vector<Index> corner_fan;
  std::vector<bool> joint;
  // Input faces only: per face, whether the propagation winds it the other way (corners 1 and
  // 2 swapped, so that every patch is wound alike); empty where none is.
  std::vector<bool> rewound;
  // Barycentric weights in the input face's corner order -> in the propagation's.
  void to_propagation_corners(Index f, std::array<double, 3>& b) const {
    if (!rewound.empty() && rewound[f]) std::swap(b[1], b[2]);
  }
};

struct WindowField::Data {
  const WindowGeodesics::Impl* mesh = nullptr;
  unsigned k = 0;                              // windows per face
  std::vector<Index> block;                    // per face: its block of k windows; kInvalidIndex unreached
  std::vector<detail::windows::Window> win;    // face f: win[block[f] * k, block[f] * k + count[f])
  std::vector<std::uint8_t> count;
};

}  // namespace gsp
