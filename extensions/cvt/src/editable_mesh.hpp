#pragma once
// A mesh edited by splits and flips with its directed edges and faces per vertex kept up to date,
// and a log of the edits since begin(): the far-point insertions try several splits of which
// they keep at most one, and judge it by the faces it changed.
#include "triangle_geometry.hpp"

#include <gsp/mesh.hpp>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gsp::cvt::detail {

class EditableMesh {
 public:
  explicit EditableMesh(TriangleMesh& m);
  const TriangleMesh& mesh() const { return m_; }
  const std::vector<Index>& faces_of(Index v) const { return faces_of_[v]; }
  // The face with directed edge (a, b), or kInvalidIndex.
  Index face_with(Index a, Index b) const {
    const auto it = directed_.find(edge_key(a, b));
    return it == directed_.end() ? kInvalidIndex : it->second;
  }
  bool edge_exists(Index a, Index b) const { return face_with(a, b) != kInvalidIndex || face_with(b, a) != kInvalidIndex; }

  // Starts a new log: the edits before it are kept for good.
  void begin() {
    old_.clear();
    faces0_ = m_.num_faces(), vertices0_ = m_.num_vertices();
  }
  Index add_vertex(Vec3 p);
  void set(Index f, const Triangle& t);
  Index add(const Triangle& t);
  // The faces changed since begin(): edited ones and added ones.
  std::vector<Index> changed() const;
  // The triangles the changed ones replaced.
  std::vector<Triangle> replaced() const;
  void rollback();

 private:
  void link(Index f);
  void unlink(Index f);
  TriangleMesh& m_;
  std::unordered_map<std::uint64_t, Index> directed_;
  std::vector<std::vector<Index>> faces_of_;
  std::vector<std::pair<Index, Triangle>> old_;
  std::size_t faces0_ = 0, vertices0_ = 0;
};

}  // namespace gsp::cvt::detail
