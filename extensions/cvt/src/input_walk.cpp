#include "input_walk.hpp"

#include <gsp/connectivity.hpp>

#include <algorithm>

namespace gsp::cvt::detail {

InputWalk::InputWalk(const TriangleMesh& input) : mesh_(input), across_(3 * input.num_faces(), kInvalidIndex) {
  // An edge of exactly two faces links them (either orientation): a radial ring of two.
  const Connectivity conn = build_connectivity(input);
  for (Index h = 0; h < across_.size(); ++h) {
    const Index g = conn.radial_next[h];
    if (g != h && conn.radial_next[g] == h && face_of(g) != face_of(h)) across_[h] = face_of(g);
  }
}

std::pair<Index, std::array<double, 3>> InputWalk::locate(Index start, Vec3 x, bool clamp) const {
  Index f = start, best = start, previous = kInvalidIndex;
  std::array<double, 3> b = affine_coordinates(mesh_, f, x), best_b = b;
  double best_min = b[0] == 0 && b[1] == 0 && b[2] == 0 ? -1.0 : *std::min_element(b.begin(), b.end());
  for (int step = 0; step < 1000 && best_min < -1e-12; ++step) {
    // The edge facing the most negative coordinate (corner k faces edge k + 1 -> k + 2),
    // never straight back where the walk came from; a face of no area (all coordinates 0)
    // holds nothing and is left by any other edge.
    const bool flat = b[0] == 0 && b[1] == 0 && b[2] == 0;
    int k = -1;
    for (int i = 0; i < 3; ++i) {
      const Index next = across_[3 * f + (i + 1) % 3];
      if ((b[i] < -1e-12 || flat) && next != kInvalidIndex && next != previous && (k < 0 || b[i] < b[k])) k = i;
    }
    if (k < 0) break;
    previous = f;
    f = across_[3 * f + (k + 1) % 3];
    b = affine_coordinates(mesh_, f, x);
    const bool none = b[0] == 0 && b[1] == 0 && b[2] == 0;
    const double m = *std::min_element(b.begin(), b.end());
    if (!none && m > best_min) best_min = m, best = f, best_b = b;
  }
  if (clamp) {
    double sum = 0;
    for (double& c : best_b) sum += (c = std::max(c, 0.0));
    if (sum > 0)
      for (double& c : best_b) c /= sum;
    else
      best_b = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  }
  return {best, best_b};
}

}  // namespace gsp::cvt::detail
