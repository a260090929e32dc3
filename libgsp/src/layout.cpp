#include <gsp/errors.hpp>
#include <gsp/layout.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>

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
  std::vector<Index> stack;
  for (std::size_t c = 0; c < clusters; ++c)
    if (cluster_node[c] >= nv) tree.append_leaves(cluster_node[c], order, stack);
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

TriangleMesh apply_layout(const TriangleMesh& mesh, const Layout& layout) {
  const std::size_t nv = mesh.num_vertices(), nf = mesh.num_faces();
  if (layout.vertex_order.size() != nv || layout.vertex_rank.size() != nv ||
      layout.face_order.size() != nf || layout.face_rank.size() != nf)
    throw InvalidInput("layout sizes (" + std::to_string(layout.vertex_order.size()) + " vertices, " +
                       std::to_string(layout.face_order.size()) + " faces) do not match the mesh (" +
                       std::to_string(nv) + ", " + std::to_string(nf) + ")");
  const bool has_normals = mesh.normals.size() == nv && nv > 0;
  TriangleMesh out;
  out.positions.resize(nv);
  if (has_normals) out.normals.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const Index old = layout.vertex_order[i];
    if (old >= nv) throw InvalidInput("layout names vertex " + std::to_string(old) + " out of range");
    out.positions[i] = mesh.positions[old];
    if (has_normals) out.normals[i] = mesh.normals[old];
  }
  out.triangles.resize(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    const Index old = layout.face_order[i];
    if (old >= nf) throw InvalidInput("layout names face " + std::to_string(old) + " out of range");
    for (int c = 0; c < 3; ++c) {
      const Index v = mesh.triangles[old][c];
      if (v >= nv) throw InvalidInput("triangle index " + std::to_string(v) + " out of range");
      out.triangles[i][c] = layout.vertex_rank[v];
    }
  }
  return out;
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
