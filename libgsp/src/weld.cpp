#include <gsp/errors.hpp>
#include <gsp/weld.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace gsp {
namespace {

std::uint64_t mix64(std::uint64_t x) {  // splitmix64 finaliser: a cheap, well-spread hash
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The bit pattern of a coordinate, with -0.0 folded onto +0.0 (they compare equal, and a
// reader may produce either for the same point).
std::uint64_t coordinate_bits(double d) {
  if (d == 0.0) d = 0.0;
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

std::size_t table_size_for(std::size_t n) {
  std::size_t size = 16;
  while (size < 2 * n) size *= 2;
  return size;
}

// An open-addressing hash table from a 3-word key to an Index, sized once for n keys, so
// nothing allocates inside the loops and every operation is expected O(1).
class KeyTable {
 public:
  using Key = std::array<std::uint64_t, 3>;
  explicit KeyTable(std::size_t n) : mask_(table_size_for(n) - 1), keys_(mask_ + 1), values_(mask_ + 1, kInvalidIndex) {}

  // The slot holding `key`, or the empty slot where it would go.
  std::size_t slot(const Key& key) const {
    std::size_t s = mix64(key[0] ^ mix64(key[1] ^ mix64(key[2]))) & mask_;
    while (values_[s] != kInvalidIndex && keys_[s] != key) s = (s + 1) & mask_;
    return s;
  }
  Index value(std::size_t s) const { return values_[s]; }
  void set(std::size_t s, const Key& key, Index v) { keys_[s] = key, values_[s] = v; }

 private:
  std::size_t mask_;
  std::vector<Key> keys_;
  std::vector<Index> values_;
};

// Grid cell of a coordinate. Clamping keeps far-away cells adjacent-or-equal (floor and clamp
// are both monotone), so the 27-cell search stays correct; it only gets slower there.
std::uint64_t cell_coordinate(double x, double inv_cell) {
  constexpr double kLimit = 4.0e18;
  const double c = std::clamp(std::floor(x * inv_cell), -kLimit, kLimit);
  return static_cast<std::uint64_t>(static_cast<std::int64_t>(c));
}

// vertex_map[i] = representative input vertex of i (the lowest index of its group): equal
// bit patterns, or with step > 0 equal coordinates rounded to multiples of step.
std::vector<Index> representatives_exact(const TriangleMesh& mesh, double step = 0.0) {
  const std::size_t n = mesh.num_vertices();
  std::vector<Index> rep(n);
  KeyTable table(n);
  const double inv_step = step > 0 ? 1.0 / step : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = mesh.positions[i];
    // Rounded to the nearest step (cells centred on the multiples, so +-noise around 0 meet).
    auto rounded = [&](double x) { return cell_coordinate(x * inv_step + 0.5, 1.0); };
    const KeyTable::Key key = step > 0 ? KeyTable::Key{rounded(p.x), rounded(p.y), rounded(p.z)}
                                       : KeyTable::Key{coordinate_bits(p.x), coordinate_bits(p.y), coordinate_bits(p.z)};
    const std::size_t s = table.slot(key);
    if (table.value(s) == kInvalidIndex) table.set(s, key, static_cast<Index>(i));
    rep[i] = table.value(s);
  }
  return rep;
}

// Vertices in input order; each joins the lowest-index representative within `tolerance`
// found in the 27 cells around it, or becomes a representative itself. Only representatives
// are stored in the grid, so groups do not chain and the result is deterministic.
std::vector<Index> representatives_tolerant(const TriangleMesh& mesh, double tolerance) {
  const std::size_t n = mesh.num_vertices();
  // Cells a hair larger than the tolerance: two points closer than it then lie in the same or
  // adjacent cells even after the rounding of x / cell.
  const double inv_cell = 1.0 / (tolerance * (1.0 + 1e-6));
  const double tol2 = tolerance * tolerance;
  std::vector<Index> rep(n);
  std::vector<Index> next_in_cell(n, kInvalidIndex);  // singly linked list of reps per cell
  KeyTable table(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = mesh.positions[i];
    const std::uint64_t cx = cell_coordinate(p.x, inv_cell), cy = cell_coordinate(p.y, inv_cell),
                        cz = cell_coordinate(p.z, inv_cell);
    Index best = kInvalidIndex;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const KeyTable::Key key{cx + dx, cy + dy, cz + dz};
          for (Index r = table.value(table.slot(key)); r != kInvalidIndex; r = next_in_cell[r]) {
            const Vec3 d = mesh.positions[r] - p;
            if (r < best && dot(d, d) < tol2) best = r;
          }
        }
    if (best != kInvalidIndex) {
      rep[i] = best;
      continue;
    }
    rep[i] = static_cast<Index>(i);
    const KeyTable::Key key{cx, cy, cz};
    const std::size_t s = table.slot(key);
    next_in_cell[i] = table.value(s);  // kInvalidIndex for a new cell
    table.set(s, key, static_cast<Index>(i));
  }
  return rep;
}

// The welded mesh for representatives rep (rep[i] <= i).
WeldResult weld_with(const TriangleMesh& mesh, const std::vector<Index>& rep) {
  const std::size_t n = mesh.num_vertices();
  const bool has_normals = mesh.normals.size() == n && n > 0;

  // Welded vertices keep the order of their representatives (first appearance in the input).
  WeldResult out;
  out.vertex_map.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (rep[i] == i) {
      out.vertex_map[i] = static_cast<Index>(out.mesh.positions.size());
      out.mesh.positions.push_back(mesh.positions[i]);
      if (has_normals) out.mesh.normals.push_back(mesh.normals[i]);
    } else {
      out.vertex_map[i] = out.vertex_map[rep[i]];  // rep[i] < i, already numbered
    }
  }
  out.merged = n - out.mesh.positions.size();

  out.mesh.triangles.resize(mesh.num_faces());
  for (std::size_t f = 0; f < mesh.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      const Index v = mesh.triangles[f][c];
      if (v >= n) throw InvalidInput("face " + std::to_string(f) + " names vertex " + std::to_string(v) +
                                     " but there are only " + std::to_string(n));
      out.mesh.triangles[f][c] = out.vertex_map[v];
    }
  return out;
}

}  // namespace

WeldResult weld_vertices(const TriangleMesh& mesh, double tolerance) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw InvalidInput("weld tolerance must be a finite number >= 0");
  if (mesh.num_vertices() >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  return weld_with(mesh, tolerance == 0.0 ? representatives_exact(mesh) : representatives_tolerant(mesh, tolerance));
}

WeldResult weld_vertices_denoised(const TriangleMesh& mesh) {
  if (mesh.num_vertices() >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  const BoundingBox box = bounding_box(mesh);
  const double diagonal = mesh.num_vertices() > 0 ? distance(box.min, box.max) : 0.0;
  // A box without extent (or without a finite one) has nothing to round: the exact weld.
  const double step = std::isfinite(diagonal) ? kWeldNoise * diagonal : 0.0;
  return weld_with(mesh, representatives_exact(mesh, step > 0 ? step : 0.0));
}

WeldResult weld_input(const TriangleMesh& mesh, double tolerance) {
  return tolerance > 0 ? weld_vertices(mesh, tolerance) : weld_vertices_denoised(mesh);
}

}  // namespace gsp
