#include "face_frames.hpp"

#include "intrinsic_geometry.hpp"

#include <algorithm>

namespace gsp::detail {

FaceFrames::FaceFrames(const FlipReplay& replay, const std::vector<Triangle>& triangles,
                       const std::vector<Triangle>& flipped, const std::vector<double>& length,
                       const std::vector<bool>& skipped)
    : begin_(triangles.size() + 1, 0) {
  // The centroid first (the flipped face holding most of a small face), then near each corner.
  constexpr double kNear = 0.9, kFar = (1 - kNear) / 2, kThird = 1.0 / 3;
  static constexpr double kProbes[4][3] = {
      {kThird, kThird, kThird}, {kNear, kFar, kFar}, {kFar, kNear, kFar}, {kFar, kFar, kNear}};
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    begin_[f] = Index(frames_.size());
    if (skipped[f] || !replay.rewritten(Index(f))) continue;
    const std::size_t first = frames_.size();
    for (const auto& probe : kProbes) {
      const FlipReplay::Frame frame = replay.frame(Index(f), triangles[f], probe, flipped);
      if (std::any_of(frames_.begin() + std::ptrdiff_t(first), frames_.end(),
                      [&](const FaceFrame& x) { return x.face == frame.face; }))
        continue;
      FaceFrame out{frame.face, {}};
      double g[3][2];
      canonical_corners(length, frame.face, 1.0, g);
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i)
          out.at[c][0] += frame.corner[c][i] * g[i][0], out.at[c][1] += frame.corner[c][i] * g[i][1];
      frames_.push_back(out);
    }
  }
  begin_.back() = Index(frames_.size());
}

}  // namespace gsp::detail
