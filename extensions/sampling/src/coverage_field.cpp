#include "coverage_field.hpp"

#include <gsp/surface_point.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::sampling::detail {

CoverageField::CoverageField(const TriangleMesh& mesh, const std::vector<bool>& referenced, double radius)
    : vertex_(referenced.size(), std::numeric_limits<double>::infinity()),
      run_vertex_(referenced.size(), std::numeric_limits<double>::infinity()),
      round_(mesh),
      centroid_radius_(mesh.num_faces(), 0.0),
      head_(mesh.num_faces(), -1),
      sample_head_(mesh.num_faces(), -1),
      source_count_(mesh.num_faces(), 0),
      sample_count_(mesh.num_faces(), 0),
      source_cells_(radius),
      sample_cells_(radius),
      mesh_(mesh),
      referenced_(referenced),
      radius_(radius) {
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 c = (1.0 / 3) * (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]);
    for (Index v : t) centroid_radius_[f] = std::max(centroid_radius_[f], distance(c, mesh.positions[v]));
  }
  for (bool r : referenced) referenced_count_ += r;
  // A maximal Poisson set's discs cover the surface about three times: one entry per face each.
  pool_.reserve(3 * mesh.num_faces());
  uncovered_ = referenced_count_;
}

VertexFaces::VertexFaces(const TriangleMesh& mesh) : begin(mesh.num_vertices() + 1, 0) {
  for (const Triangle& t : mesh.triangles)
    for (Index v : t) ++begin[v + 1];
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) begin[v + 1] += begin[v];
  faces.resize(begin.back());
  std::vector<Index> fill(begin.begin(), begin.end() - 1);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (Index v : mesh.triangles[f]) faces[fill[v]++] = Index(f);
}

bool CoverageField::clear_of_samples(const LocalField& run) const {
  // Through a corner (corner_paths): the samples of the faces round every vertex the run
  // reached within r, where a face holds few (more than kDense: a face large against r, whose
  // own virtual source is what reaches its inside). By vertex, not by the run's faces: a
  // sliver whose one virtual source reads as farther than r is not among those.
  for (std::size_t k = 0; k < run.vertices.size(); ++k) run_vertex_[run.vertices[k]] = run.vertex_distance[k];
  bool clear = true;
  for (std::size_t k = 0; k < run.vertices.size() && clear; ++k) {
    const Index v = run.vertices[k];
    for (Index c = round_.begin[v]; c < round_.begin[v + 1] && clear; ++c) {
      const Index f = round_.faces[c];
      for (std::int32_t e = sample_count_[f] <= kDense ? sample_head_[f] : -1; e >= 0 && clear; e = sample_next_[e])
        clear = !(corner_paths(mesh_, f, sample_position_[e], run_vertex_) < radius_);
    }
  }
  for (std::size_t k = 0; k < run.faces.size() && clear; ++k) {
    const Index f = run.faces[k];
    if (sample_head_[f] < 0 || !near(run, k)) continue;
    const VirtualSource& vs = run.face_sources[k];
    bool close = false;
    auto check = [&](std::int32_t e) { close = close || vs.sigma + distance(sample_position_[e], vs.position) < radius_; };
    if (sample_count_[f] > kDense)
      sample_cells_.near(f, vs.position, check);   // a sample closer than r - sigma lies in the cubes around it
    else
      for (std::int32_t e = sample_head_[f]; e >= 0 && !close; e = sample_next_[e]) check(e);
    clear = !close;
  }
  for (Index v : run.vertices) run_vertex_[v] = std::numeric_limits<double>::infinity();
  return clear;
}

void CoverageField::add_sample(Index face, const std::array<double, 3>& barycentric) {
  const std::int32_t e = std::int32_t(sample_next_.size());
  sample_next_.push_back(sample_head_[face]);
  sample_head_[face] = e;
  sample_position_.push_back(SurfacePoint::in_face(face, barycentric).position(mesh_));
  if (++sample_count_[face] == kDense + 1)   // from now on in the cubes, these included
    for (std::int32_t i = e; i >= 0; i = sample_next_[i]) sample_cells_.add(face, sample_position_[i], i);
  else if (sample_count_[face] > kDense)
    sample_cells_.add(face, sample_position_[e], e);
}

void CoverageField::add_source(Index face, Vec3 position, double sigma) {
  const std::int32_t e = std::int32_t(pool_.size());
  pool_.push_back({position, sigma, head_[face]});
  head_[face] = e;
  if (++source_count_[face] == kDense + 1)
    for (std::int32_t i = e; i >= 0; i = pool_[i].next) source_cells_.add(face, pool_[i].position, i);
  else if (source_count_[face] > kDense)
    source_cells_.add(face, position, e);
}

void CoverageField::merge(const LocalField& run) {
  for (std::size_t k = 0; k < run.vertices.size(); ++k) {
    const Index v = run.vertices[k];
    const double d = run.vertex_distance[k];
    if (!(d < vertex_[v])) continue;
    if (referenced_[v] && vertex_[v] >= radius_ && d < radius_) --uncovered_;
    vertex_[v] = d;
  }
  for (std::size_t k = 0; k < run.faces.size(); ++k) {
    if (!near(run, k)) continue;
    const VirtualSource& vs = run.face_sources[k];
    add_source(run.faces[k], vs.position, vs.sigma);
  }
}

}  // namespace gsp::sampling::detail
