#include <gsp/errors.hpp>
#include <gsp/layout.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string>
#include <utility>

namespace gsp {
namespace {

// An undirected edge between nodes u < v of a graph, with a multiplicity.
struct WeightedEdge {
  Index u, v, w;
};

// Sorts edges by (u, v) with two stable counting passes (v, then u) and merges equal pairs,
// summing weights. Linear in edges + nodes; the (u, v) order is also the tie-breaking key of
// the clustering, so the result never depends on hashing or on std::sort's implementation.
void sort_and_merge_edges(std::vector<WeightedEdge>& edges, std::size_t nodes,
                          std::vector<WeightedEdge>& scratch, std::vector<Index>& counts) {
  scratch.resize(edges.size());
  auto counting_pass = [&](const std::vector<WeightedEdge>& in, std::vector<WeightedEdge>& out,
                           Index WeightedEdge::*field) {
    counts.assign(nodes + 1, 0);
    for (const WeightedEdge& e : in) ++counts[e.*field + 1];
    for (std::size_t i = 0; i < nodes; ++i) counts[i + 1] += counts[i];
    for (const WeightedEdge& e : in) out[counts[e.*field]++] = e;
  };
  counting_pass(edges, scratch, &WeightedEdge::v);
  counting_pass(scratch, edges, &WeightedEdge::u);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (kept > 0 && edges[kept - 1].u == edges[i].u && edges[kept - 1].v == edges[i].v)
      edges[kept - 1].w += edges[i].w;
    else
      edges[kept++] = edges[i];
  }
  edges.resize(kept);
}

// The undirected edges of the mesh (each once, weight 1), sorted by (smaller, larger) vertex.
std::vector<WeightedEdge> mesh_edges(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  std::vector<WeightedEdge> edges;
  edges.reserve(3 * mesh.num_faces());
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) {
      const Index a = t[i], b = t[(i + 1) % 3];
      if (a >= nv || b >= nv) throw InvalidInput("triangle index " + std::to_string(std::max(a, b)) + " out of range");
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b), 1});
    }
  std::vector<WeightedEdge> scratch;
  std::vector<Index> counts;
  sort_and_merge_edges(edges, nv, scratch, counts);
  for (WeightedEdge& e : edges) e.w = 1;
  return edges;
}

// Faces ordered by their sorted new vertex indices (smallest first, then the other two, then
// the input order): three stable counting passes, least significant key first.
std::vector<Index> faces_by_smallest_vertex(const TriangleMesh& mesh, const std::vector<Index>& vertex_rank) {
  const std::size_t nf = mesh.num_faces(), nv = mesh.num_vertices();
  std::vector<Triangle> keys(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    Triangle k{vertex_rank[mesh.triangles[f][0]], vertex_rank[mesh.triangles[f][1]], vertex_rank[mesh.triangles[f][2]]};
    std::sort(k.begin(), k.end());
    keys[f] = k;
  }
  std::vector<Index> order(nf), scratch(nf), counts;
  std::iota(order.begin(), order.end(), Index{0});
  for (int digit = 2; digit >= 0; --digit) {
    counts.assign(nv + 1, 0);
    for (Index f : order) ++counts[keys[f][digit] + 1];
    for (std::size_t i = 0; i < nv; ++i) counts[i + 1] += counts[i];
    for (Index f : order) scratch[counts[keys[f][digit]]++] = f;
    order.swap(scratch);
  }
  return order;
}

std::vector<Index> inverse_permutation(const std::vector<Index>& order) {
  std::vector<Index> rank(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = static_cast<Index>(i);
  return rank;
}

Layout layout_from_vertex_order(const TriangleMesh& mesh, std::vector<Index> vertex_order) {
  Layout l;
  l.vertex_order = std::move(vertex_order);
  l.vertex_rank = inverse_permutation(l.vertex_order);
  l.face_order = faces_by_smallest_vertex(mesh, l.vertex_rank);
  l.face_rank = inverse_permutation(l.face_order);
  return l;
}

// Merge tree of the clustering: nodes [0, nv) are the vertices, node nv + i is the i-th merge.
struct MergeTree {
  std::size_t leaves = 0;
  std::vector<Index> left, right;  // children of internal node nv + i
  Index merge(Index a, Index b) {
    left.push_back(a);
    right.push_back(b);
    return static_cast<Index>(leaves + left.size() - 1);
  }
  // Leaves under `root`, left to right, appended to `out` (iterative: trees can be deep).
  void append_leaves(Index root, std::vector<Index>& out, std::vector<Index>& stack) const {
    stack.assign(1, root);
    while (!stack.empty()) {
      const Index n = stack.back();
      stack.pop_back();
      if (n < leaves) {
        out.push_back(n);
      } else {
        stack.push_back(right[n - leaves]);
        stack.push_back(left[n - leaves]);
      }
    }
  }
};

// Turns subtrees around so that the vertices joined to the sibling cluster sit at the boundary
// the two share in the order. The clustering decides which vertices are together; this decides
// which end of a cluster faces its neighbour. Without it the few long index gaps between large
// clusters dominate the mean neighbour index distance (armadillo: 162 against its file order's
// 139; with it 120). Top-down: a decision reverses the cluster's stretch of `order` in place.
void orient_subtrees(const MergeTree& tree, Index root, std::size_t begin, std::vector<Index>& order,
                     std::vector<Index>& position, const std::vector<Index>& size,
                     const std::vector<Index>& adj_begin, const std::vector<Index>& adj) {
  struct Item {
    Index node;
    std::size_t begin;
    bool reversed;
  };
  std::vector<Item> stack{{root, begin, false}};
  auto reverse = [&](std::size_t s, std::size_t e) {
    std::reverse(order.begin() + s, order.begin() + e);
    for (std::size_t i = s; i < e; ++i) position[order[i]] = Index(i);
  };
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    if (it.node < tree.leaves) continue;
    const Index l = tree.left[it.node - tree.leaves], r = tree.right[it.node - tree.leaves];
    Index first = it.reversed ? r : l, second = it.reversed ? l : r;
    const std::size_t s = it.begin, m = s + size[first], e = m + size[second];
    bool flip_first = false, flip_second = false;
    if (size[first] > 1 && size[second] > 1) {
      // Mean positions of the endpoints of the edges between the two, found from the smaller.
      double sum_first = 0, sum_second = 0;
      std::size_t n = 0;
      const bool from_first = size[first] <= size[second];
      const std::size_t from_s = from_first ? s : m, from_e = from_first ? m : e;
      const std::size_t to_s = from_first ? m : s, to_e = from_first ? e : m;
      for (std::size_t i = from_s; i < from_e; ++i)
        for (Index k = adj_begin[order[i]]; k < adj_begin[order[i] + 1]; ++k) {
          const Index p = position[adj[k]];
          if (p < to_s || p >= to_e) continue;
          (from_first ? sum_first : sum_second) += double(i);
          (from_first ? sum_second : sum_first) += double(p);
          ++n;
        }
      if (n > 0) {
        flip_first = sum_first / double(n) < 0.5 * double(s + m - 1);
        flip_second = sum_second / double(n) > 0.5 * double(m + e - 1);
      }
    }
    if (flip_first) reverse(s, m);
    if (flip_second) reverse(m, e);
    stack.push_back({second, m, it.reversed != flip_second});
    stack.push_back({first, s, it.reversed != flip_first});
  }
}

struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in [0, bound) without modulo bias: reject the few values of the incomplete
  // last block of 2^64.
  std::uint64_t below(std::uint64_t bound) {
    const std::uint64_t threshold = (0 - bound) % bound;
    for (;;) {
      const std::uint64_t r = next();
      if (r >= threshold) return r % bound;
    }
  }
};

template <class T>
void shuffle(std::vector<T>& v, SplitMix64& rng) {  // Fisher-Yates, back to front
  for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

}  // namespace

Layout compute_cache_layout(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (nv >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");

  // Round state: clusters are numbered 0..C-1 afresh each round; `edges` is the cluster graph
  // (weights = mesh edges between the two clusters), sorted by (u, v).
  std::vector<WeightedEdge> edges = mesh_edges(mesh);
  std::vector<Index> cluster_node(nv), cluster_size(nv, 1);
  std::iota(cluster_node.begin(), cluster_node.end(), Index{0});
  std::size_t clusters = nv;

  MergeTree tree;
  tree.leaves = nv;
  tree.left.reserve(nv);
  tree.right.reserve(nv);

  std::vector<Index> parent, by_weight, counts, new_id;
  std::vector<WeightedEdge> scratch;
  // Round k allows clusters of 2^k vertices; round 0 (limit 1) can merge nothing, so start at 1.
  for (std::uint64_t limit = 2; !edges.empty(); limit *= 2) {
    // Edges by descending weight, (u, v) order among equal weights: a stable counting sort.
    Index max_weight = 0;
    for (const WeightedEdge& e : edges) max_weight = std::max(max_weight, e.w);
    counts.assign(std::size_t{max_weight} + 2, 0);
    for (const WeightedEdge& e : edges) ++counts[max_weight - e.w + 1];
    for (std::size_t i = 0; i <= max_weight; ++i) counts[i + 1] += counts[i];
    by_weight.resize(edges.size());
    for (Index i = 0; i < edges.size(); ++i) by_weight[counts[max_weight - edges[i].w]++] = i;

    // Greedy merging with union-find; the lower cluster number stays the root, so cluster
    // numbers keep following the input order of their first vertex.
    parent.resize(clusters);
    std::iota(parent.begin(), parent.end(), Index{0});
    auto find = [&](Index x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::size_t merges = 0;
    for (Index i : by_weight) {
      const Index a = find(edges[i].u), b = find(edges[i].v);
      if (a == b || std::uint64_t{cluster_size[a]} + cluster_size[b] > limit) continue;
      const Index root = std::min(a, b), child = std::max(a, b);
      cluster_node[root] = tree.merge(cluster_node[root], cluster_node[child]);
      cluster_size[root] += cluster_size[child];
      parent[child] = root;
      ++merges;
    }
    if (merges == 0) continue;  // every candidate too big for this limit: try the next one

    // Renumber the surviving clusters and contract the cluster graph: it shrinks with the
    // number of clusters, so the rounds together cost little more than the first.
    new_id.resize(clusters);
    std::size_t next = 0;
    for (Index c = 0; c < clusters; ++c)
      if (parent[c] == c) {
        new_id[c] = static_cast<Index>(next);
        cluster_node[next] = cluster_node[c];
        cluster_size[next] = cluster_size[c];
        ++next;
      }
    for (Index c = 0; c < clusters; ++c) new_id[c] = new_id[find(c)];
    clusters = next;
    std::size_t kept = 0;
    for (const WeightedEdge& e : edges) {
      const Index a = new_id[e.u], b = new_id[e.v];
      if (a != b) edges[kept++] = {std::min(a, b), std::max(a, b), e.w};
    }
    edges.resize(kept);
    sort_and_merge_edges(edges, clusters, scratch, counts);
  }

  // One tree per connected component, in the order of their first input vertex; vertices
  // on no edge (unreferenced, or only in faces naming one vertex thrice) go last.
  std::vector<Index> order;
  order.reserve(nv);
  std::vector<Index> stack, roots;
  for (std::size_t c = 0; c < clusters; ++c)
    if (cluster_node[c] >= nv) roots.push_back(cluster_node[c]);
  std::vector<std::size_t> root_begin;
  for (Index root : roots) {
    root_begin.push_back(order.size());
    tree.append_leaves(root, order, stack);
  }
  {
    // Leaf counts per node (children are always created before their parent), positions, and
    // the vertex adjacency, for orient_subtrees.
    std::vector<Index> size(nv + tree.left.size(), 1);
    for (std::size_t i = 0; i < tree.left.size(); ++i) size[nv + i] = size[tree.left[i]] + size[tree.right[i]];
    std::vector<Index> position(nv, 0);
    for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = Index(i);
    const std::vector<WeightedEdge> all = mesh_edges(mesh);
    std::vector<Index> adj_begin(nv + 1, 0), adj(2 * all.size());
    for (const WeightedEdge& e : all) ++adj_begin[e.u + 1], ++adj_begin[e.v + 1];
    for (std::size_t v = 0; v < nv; ++v) adj_begin[v + 1] += adj_begin[v];
    std::vector<Index> fill(adj_begin.begin(), adj_begin.end() - 1);
    for (const WeightedEdge& e : all) adj[fill[e.u]++] = e.v, adj[fill[e.v]++] = e.u;
    // A second pass sees the inner orientations the first one chose (armadillo: 145 after one
    // pass, 120 after two, no further gain from a third).
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t i = 0; i < roots.size(); ++i)
        orient_subtrees(tree, roots[i], root_begin[i], order, position, size, adj_begin, adj);
  }
  std::vector<bool> placed(nv, false);
  for (Index v : order) placed[v] = true;
  for (Index v = 0; v < nv; ++v)
    if (!placed[v]) order.push_back(v);
  return layout_from_vertex_order(mesh, std::move(order));
}

Layout random_layout(const TriangleMesh& mesh, std::uint64_t seed) {
  SplitMix64 rng{seed};
  Layout l;
  l.vertex_order.resize(mesh.num_vertices());
  std::iota(l.vertex_order.begin(), l.vertex_order.end(), Index{0});
  shuffle(l.vertex_order, rng);
  l.face_order.resize(mesh.num_faces());
  std::iota(l.face_order.begin(), l.face_order.end(), Index{0});
  shuffle(l.face_order, rng);
  l.vertex_rank = inverse_permutation(l.vertex_order);
  l.face_rank = inverse_permutation(l.face_order);
  return l;
}

namespace {

// The 21 low bits of x spread to every third bit (x -> x0 0 0 x1 0 0 x2 ...).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

Layout spatial_layout(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (nv >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  const BoundingBox box = bounding_box(mesh);
  const Vec3 size = box.max - box.min;
  const double extent = std::max({size.x, size.y, size.z});
  const double scale = extent > 0 ? double((1u << 21) - 1) / extent : 0.0;
  // (Morton code, vertex): sorted, the vertices follow a Z-order curve through the box.
  std::vector<std::pair<std::uint64_t, Index>> key(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3 q = scale * (mesh.positions[v] - box.min);
    key[v] = {spread_bits(std::uint64_t(q.x)) | spread_bits(std::uint64_t(q.y)) << 1 | spread_bits(std::uint64_t(q.z)) << 2,
              Index(v)};
  }
  std::sort(key.begin(), key.end());
  std::vector<Index> order(nv);
  for (std::size_t i = 0; i < nv; ++i) order[i] = key[i].second;
  return layout_from_vertex_order(mesh, std::move(order));
}

Layout face_order_layout(const TriangleMesh& mesh) {
  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  if (nv >= kInvalidIndex) throw InvalidInput("mesh has too many vertices for 32-bit indices");
  Layout l;
  l.vertex_order.resize(nv);
  std::iota(l.vertex_order.begin(), l.vertex_order.end(), Index{0});
  l.vertex_rank = l.vertex_order;
  // One stable counting pass on the smallest vertex (ties keep the input's order), not the
  // other layouts' three: what the propagation needs is neighbours near each other, and three
  // passes cost a noticeable part of the run they are for (docs/layout.md, "Faces out of order").
  auto smallest = [&](std::size_t f) {
    const Triangle& t = mesh.triangles[f];
    const Index hi = std::max({t[0], t[1], t[2]});
    if (hi >= nv) throw InvalidInput("triangle index " + std::to_string(hi) + " out of range");
    return std::min({t[0], t[1], t[2]});
  };
  std::vector<Index> counts(nv + 1, 0);
  for (std::size_t f = 0; f < nf; ++f) ++counts[smallest(f) + 1];
  for (std::size_t i = 0; i < nv; ++i) counts[i + 1] += counts[i];
  l.face_order.resize(nf);
  for (std::size_t f = 0; f < nf; ++f) l.face_order[counts[smallest(f)]++] = Index(f);
  l.face_rank = inverse_permutation(l.face_order);
  return l;
}

Layout identity_layout(const TriangleMesh& mesh) {
  Layout l;
  l.vertex_order.resize(mesh.num_vertices());
  std::iota(l.vertex_order.begin(), l.vertex_order.end(), Index{0});
  l.face_order.resize(mesh.num_faces());
  std::iota(l.face_order.begin(), l.face_order.end(), Index{0});
  l.vertex_rank = l.vertex_order;
  l.face_rank = l.face_order;
  return l;
}

namespace {

void check_layout_sizes(const TriangleMesh& mesh, const Layout& layout) {
  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  if (layout.vertex_order.size() != nv || layout.vertex_rank.size() != nv ||
      layout.face_order.size() != nf || layout.face_rank.size() != nf)
    throw InvalidInput("layout sizes (" + std::to_string(layout.vertex_order.size()) + " vertices, " +
                       std::to_string(layout.face_order.size()) + " faces) do not match the mesh (" +
                       std::to_string(nv) + ", " + std::to_string(nf) + ")");
}

// Per-vertex values in the layout's order.
template <class T>
std::vector<T> vertices_in_layout(const std::vector<T>& values, const Layout& layout) {
  const std::size_t nv = values.size();
  std::vector<T> out(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const Index old = layout.vertex_order[i];
    if (old >= nv) throw InvalidInput("layout names vertex " + std::to_string(old) + " out of range");
    out[i] = values[old];
  }
  return out;
}

// The triangles in the layout's order, with the vertices' new numbers.
std::vector<Triangle> triangles_in_layout(const std::vector<Triangle>& triangles, std::size_t nv,
                                          const Layout& layout) {
  const std::size_t nf = triangles.size();
  std::vector<Triangle> out(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    const Index old = layout.face_order[i];
    if (old >= nf) throw InvalidInput("layout names face " + std::to_string(old) + " out of range");
    for (int c = 0; c < 3; ++c) {
      const Index v = triangles[old][c];
      if (v >= nv) throw InvalidInput("triangle index " + std::to_string(v) + " out of range");
      out[i][c] = layout.vertex_rank[v];
    }
  }
  return out;
}

}  // namespace

TriangleMesh apply_layout(const TriangleMesh& mesh, const Layout& layout) {
  check_layout_sizes(mesh, layout);
  const std::size_t nv = mesh.num_vertices();
  TriangleMesh out;
  out.positions = vertices_in_layout(mesh.positions, layout);
  if (mesh.normals.size() == nv && nv > 0) out.normals = vertices_in_layout(mesh.normals, layout);
  out.triangles = triangles_in_layout(mesh.triangles, nv, layout);
  return out;
}

void apply_layout_in_place(TriangleMesh& mesh, const Layout& layout) {
  check_layout_sizes(mesh, layout);
  const std::size_t nv = mesh.num_vertices();
  // The vertices kept in their order (face_order_layout): their arrays stay as they are, not
  // copied into fresh memory, whose page faults cost more than the sort itself.
  bool same_vertices = true;
  for (std::size_t v = 0; v < nv && same_vertices; ++v) same_vertices = layout.vertex_order[v] == v;
  // One array at a time, each old one freed as its new one is ready.
  if (!same_vertices) {
    mesh.positions = vertices_in_layout(mesh.positions, layout);
    if (mesh.normals.size() == nv && nv > 0) mesh.normals = vertices_in_layout(mesh.normals, layout);
    else mesh.normals.clear();
  } else if (mesh.normals.size() != nv) {
    mesh.normals.clear();
  }
  mesh.triangles = triangles_in_layout(mesh.triangles, nv, layout);
}

Layout inverse_layout(Layout layout) {
  std::swap(layout.vertex_order, layout.vertex_rank);
  std::swap(layout.face_order, layout.face_rank);
  return layout;
}

double mean_neighbour_index_distance(const TriangleMesh& mesh) {
  const std::vector<WeightedEdge> edges = mesh_edges(mesh);
  if (edges.empty()) return 0.0;
  double sum = 0.0;
  for (const WeightedEdge& e : edges) sum += static_cast<double>(e.v - e.u);
  return sum / static_cast<double>(edges.size());
}

double mean_log_neighbour_index_distance(const TriangleMesh& mesh) {
  const std::vector<WeightedEdge> edges = mesh_edges(mesh);
  if (edges.empty()) return 0.0;
  double sum = 0.0;
  for (const WeightedEdge& e : edges) sum += std::log2(1.0 + static_cast<double>(e.v - e.u));
  return sum / static_cast<double>(edges.size());
}

}  // namespace gsp
