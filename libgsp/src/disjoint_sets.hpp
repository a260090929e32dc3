#pragma once
// Union-find over 0..n-1 (internal): path halving; union by index (the smaller index stays
// root), so the result never depends on the order of unions.
#include <gsp/types.hpp>

#include <numeric>
#include <vector>

namespace gsp::detail {

struct DisjointSets {
  std::vector<Index> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index{0}); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) {
    a = find(a), b = find(b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
  }
};

}  // namespace gsp::detail
