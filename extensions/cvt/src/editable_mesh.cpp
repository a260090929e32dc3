#include "editable_mesh.hpp"

#include <algorithm>

namespace gsp::cvt::detail {

EditableMesh::EditableMesh(TriangleMesh& m) : m_(m), faces_of_(m.num_vertices()) {
  directed_.reserve(3 * m.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f) link(f);
}

Index EditableMesh::add_vertex(Vec3 p) {
  m_.positions.push_back(p);
  faces_of_.emplace_back();
  return Index(m_.positions.size() - 1);
}

void EditableMesh::set(Index f, const Triangle& t) {
  if (f < faces0_ && std::none_of(old_.begin(), old_.end(), [&](const auto& o) { return o.first == f; }))
    old_.push_back({f, m_.triangles[f]});
  unlink(f);
  m_.triangles[f] = t;
  link(f);
}

Index EditableMesh::add(const Triangle& t) {
  m_.triangles.push_back(t);
  link(Index(m_.triangles.size() - 1));
  return Index(m_.triangles.size() - 1);
}

std::vector<Index> EditableMesh::changed() const {
  std::vector<Index> c;
  for (const auto& o : old_) c.push_back(o.first);
  for (Index f = Index(faces0_); f < m_.num_faces(); ++f) c.push_back(f);
  return c;
}

std::vector<Triangle> EditableMesh::replaced() const {
  std::vector<Triangle> r;
  for (const auto& o : old_) r.push_back(o.second);
  return r;
}

void EditableMesh::rollback() {
  for (Index f = Index(faces0_); f < m_.num_faces(); ++f) unlink(f);
  for (const auto& o : old_) unlink(o.first);
  m_.triangles.resize(faces0_);
  for (const auto& o : old_) {
    m_.triangles[o.first] = o.second;
    link(o.first);
  }
  m_.positions.resize(vertices0_);
  faces_of_.resize(vertices0_);
  old_.clear();
}

void EditableMesh::link(Index f) {
  const Triangle& t = m_.triangles[f];
  for (Index k = 0; k < 3; ++k) {
    directed_[edge_key(t[k], t[(k + 1) % 3])] = f;
    faces_of_[t[k]].push_back(f);
  }
}

void EditableMesh::unlink(Index f) {
  const Triangle& t = m_.triangles[f];
  for (Index k = 0; k < 3; ++k) {
    const auto it = directed_.find(edge_key(t[k], t[(k + 1) % 3]));
    if (it != directed_.end() && it->second == f) directed_.erase(it);
    std::vector<Index>& fs = faces_of_[t[k]];
    const auto jt = std::find(fs.begin(), fs.end(), f);
    if (jt != fs.end()) fs.erase(jt);
  }
}

}  // namespace gsp::cvt::detail
