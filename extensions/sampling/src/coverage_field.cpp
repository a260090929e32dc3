#include "coverage_field.hpp"

#include <cmath>

namespace gsp::sampling::detail {

CoverageField::CoverageField(std::size_t num_faces, const std::vector<bool>& referenced, double radius)
    : vertex_(referenced.size(), std::numeric_limits<double>::infinity()),
      head_(num_faces, -1),
      sample_head_(num_faces, -1),
      referenced_(referenced),
      radius_(radius) {
  for (bool r : referenced) referenced_count_ += r;
  uncovered_ = referenced_count_;
}

bool CoverageField::clear_of_samples(const GeodesicResult& run, const TriangleMesh& mesh, double radius,
                                     double keep_face_distance) const {
  const std::size_t nf = sample_head_.size();
  for (std::size_t f = 0; f < nf; ++f) {
    if (sample_head_[f] < 0 || !(run.face_distance[f] <= keep_face_distance)) continue;
    for (std::int32_t e = sample_head_[f]; e >= 0; e = samples_[e].next)
      if (run.distance_at(mesh, Index(f), samples_[e].barycentric) < radius) return false;
  }
  return true;
}

void CoverageField::add_sample(Index face, const std::array<double, 3>& barycentric) {
  samples_.push_back({barycentric, sample_head_[face]});
  sample_head_[face] = std::int32_t(samples_.size() - 1);
}

void CoverageField::merge(const GeodesicResult& run, double keep_face_distance) {
  const std::size_t nv = vertex_.size();
  for (std::size_t v = 0; v < nv; ++v) {
    const double d = run.vertex_distance[v];
    if (!(d < vertex_[v])) continue;
    if (referenced_[v] && vertex_[v] >= radius_ && d < radius_) --uncovered_;
    vertex_[v] = d;
  }
  const std::size_t nf = head_.size();
  for (std::size_t f = 0; f < nf; ++f) {
    if (!(run.face_distance[f] <= keep_face_distance)) continue;
    const VirtualSource& vs = run.face_sources[f];
    if (!vs.reached()) continue;
    pool_.push_back({vs.position, vs.sigma, head_[f]});
    head_[f] = std::int32_t(pool_.size() - 1);
  }
}

}  // namespace gsp::sampling::detail
