#include <gsp/subdivide.hpp>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace gsp {

TriangleMesh midpoint_subdivide(const TriangleMesh& mesh, int times) {
  TriangleMesh m = mesh;
  for (int round = 0; round < times; ++round) {
    TriangleMesh out;
    out.positions = m.positions;
    out.triangles.reserve(4 * m.triangles.size());
    std::unordered_map<std::uint64_t, Index> midpoint;   // undirected edge -> its new vertex
    midpoint.reserve(3 * m.triangles.size() / 2);
    auto at = [&](Index a, Index b) {
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto [it, added] = midpoint.emplace(key, Index(out.positions.size()));
      if (added) out.positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
      return it->second;
    };
    for (const Triangle& t : m.triangles) {
      const Index ab = at(t[0], t[1]), bc = at(t[1], t[2]), ca = at(t[2], t[0]);
      out.triangles.push_back({t[0], ab, ca});
      out.triangles.push_back({ab, t[1], bc});
      out.triangles.push_back({ca, bc, t[2]});
      out.triangles.push_back({ab, bc, ca});
    }
    m = std::move(out);
  }
  return m;
}

}  // namespace gsp
