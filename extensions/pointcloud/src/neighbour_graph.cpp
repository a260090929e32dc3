// k-NN / radius graph: directed neighbour lists from the k-d tree, then symmetrised into CSR.
#include <gsp/errors.hpp>
#include <gsp/mesh.hpp>
#include <gsp/pointcloud/neighbour_graph.hpp>

#include "graph_builder.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::pointcloud {
namespace detail {

void check_options(const NeighbourOptions& options) {
  if (options.rule == Neighbourhood::knn && options.k == 0)
    throw InvalidInput("point cloud: k must be at least 1");
  if (options.rule == Neighbourhood::radius && !(options.radius > 0 && std::isfinite(options.radius)))
    throw InvalidInput("point cloud: the neighbourhood radius must be positive and finite");
}

NeighbourGraph build_graph(const std::vector<Vec3>& points, const PointTree& tree, const NeighbourOptions& options) {
  check_options(options);
  const std::size_t n = points.size();
  // Directed links (i -> j) from each point's query, both directions added, then sorted and
  // deduplicated: the union makes the graph symmetric.
  std::vector<std::pair<Index, Index>> links;
  std::vector<Index> idx(options.k + 1);
  std::vector<double> d2(options.k + 1);
  std::vector<std::pair<Index, double>> found;
  for (Index i = 0; i < n; ++i) {
    auto add = [&](Index j) {
      if (j == i) return;
      links.push_back({i, j});
      links.push_back({j, i});
    };
    if (options.rule == Neighbourhood::knn) {
      // k + 1: the query point itself comes back among the nearest.
      const std::size_t got = tree.knn(points[i], options.k + 1, idx.data(), d2.data());
      std::size_t taken = 0;
      for (std::size_t a = 0; a < got && taken < options.k; ++a) {
        if (idx[a] == i) continue;
        add(idx[a]);
        ++taken;
      }
    } else {
      tree.within(points[i], options.radius * options.radius, found);
      for (const auto& [j, dd] : found) add(j);
    }
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());

  NeighbourGraph g;
  g.begin.assign(n + 1, 0);
  g.neighbour.resize(links.size());
  g.length.resize(links.size());
  for (std::size_t e = 0; e < links.size(); ++e) {
    ++g.begin[links[e].first + 1];
    g.neighbour[e] = links[e].second;
    g.length[e] = distance(points[links[e].first], points[links[e].second]);
  }
  for (std::size_t i = 0; i < n; ++i) g.begin[i + 1] += g.begin[i];
  return g;
}

}  // namespace detail

NeighbourGraph build_neighbour_graph(const std::vector<Vec3>& points, const NeighbourOptions& options) {
  detail::check_options(options);
  validate_positions(points, "point cloud: point");
  const detail::PointTree tree(points);
  return detail::build_graph(points, tree, options);
}

Components connected_components(const NeighbourGraph& graph) {
  Components c;
  const std::size_t n = graph.num_points();
  c.id.assign(n, kInvalidIndex);
  std::vector<Index> stack;
  for (Index s = 0; s < n; ++s) {
    if (c.id[s] != kInvalidIndex) continue;
    const Index id = static_cast<Index>(c.count++);
    c.id[s] = id;
    stack.push_back(s);
    while (!stack.empty()) {
      const Index v = stack.back();
      stack.pop_back();
      for (Index e = graph.begin[v]; e < graph.begin[v + 1]; ++e) {
        const Index w = graph.neighbour[e];
        if (c.id[w] == kInvalidIndex) {
          c.id[w] = id;
          stack.push_back(w);
        }
      }
    }
  }
  return c;
}

}  // namespace gsp::pointcloud
