#pragma once
// Where each input face lies on the intrinsic Delaunay faces, for the per-face virtual sources
// of a run on them (GeodesicSolver::Impl::fitted_face_sources): per input face, the flipped
// faces it overlaps (found at its centroid and near each corner) and its own corners in each
// one's canonical frame. A face no flip rewrote is its own flipped face and has no entry. Made
// once per solver from the flip log (flip_replay.hpp), at the first query that asks for face
// sources: the walks through the flips cost more than a query on heavily flipped CAD meshes.
#include "flip_replay.hpp"

#include <gsp/mesh.hpp>

#include <vector>

namespace gsp::detail {

struct FaceFrame {
  Index face;          // a flipped face the input face overlaps
  double at[3][2];     // the input face's corners in its canonical frame (model units)
};

class FaceFrames {
 public:
  // `triangles`: the input faces (memory order); `flipped`, `length`: the flipped faces and
  // their halfedge lengths; `skipped`: faces left out (no frames).
  FaceFrames(const FlipReplay& replay, const std::vector<Triangle>& triangles, const std::vector<Triangle>& flipped,
             const std::vector<double>& length, const std::vector<bool>& skipped);
  // The frames of input face f; empty when no flip rewrote it.
  const FaceFrame* begin(Index f) const { return frames_.data() + begin_[f]; }
  const FaceFrame* end(Index f) const { return frames_.data() + begin_[f + 1]; }
  std::size_t bytes() const { return frames_.size() * sizeof(FaceFrame) + begin_.size() * sizeof(Index); }

 private:
  std::vector<Index> begin_;
  std::vector<FaceFrame> frames_;
};

}  // namespace gsp::detail
