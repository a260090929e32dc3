#include "component_remesh.hpp"
#include "edge_remesh.hpp"
#include "post_pass.hpp"

#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/components.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

namespace gsp::cvt::detail {

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kMinAngleDeg = 20;   // issue 22's quality floor

std::string fixed2(double x, const char* unit) {
  char b[48];
  std::snprintf(b, sizeof b, "%.2f%s", x, unit);
  return b;
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Orients the component alike, keeping the orientation most of its faces had (so a mesh with
// a few flipped faces keeps its normals). Returns the faces whose orientation changed.
std::size_t orient_by_majority(TriangleMesh& m) {
  const std::int64_t flipped = orient_consistently(m);
  if (2 * std::size_t(flipped) <= m.num_faces()) return std::size_t(flipped);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m.num_faces() - std::size_t(flipped);
}

// The remesh by edge operations (edge_remesh.hpp) of a component no CVT dual had the topology
// of, at the spacing of its share of the sites, then the dual's post-pass. Kept where it has the
// component's topology, a smallest angle of at least 20 degrees or at least the input's own, and
// no larger share of angles below 30 degrees than the input: never worse than keeping the input
// (as for a small component raised above its share), which a modelled part's well-shaped input
// can be against a remesh with needles at a handle thinner than the spacing. Empty where not;
// `why` says why. `min_angle`: the kept remesh's smallest angle (degrees).
TriangleMesh edge_operations_remesh(const TriangleMesh& oriented, double area, std::size_t sites, const CvtOptions& co,
                                    const SurfaceRemeshOptions& options, RemeshStats& remesh_stats, std::string& why,
                                    double& min_angle) {
  // N = 2 A / (sqrt(3) L^2), as CvtOptions::edge_length converts it.
  const double length = std::sqrt(2 * area / (std::sqrt(3.0) * double(std::max<std::size_t>(sites, 1))));
  const ClosestPointIndex surface(oriented);
  // The splits may pass through many more vertices than the share where they cut a CAD part's
  // fans of needles before the collapses thin them out (the boiler section at 5,000 sites:
  // 190,000); a hundred times the share bounds the memory (about 300 bytes a vertex in
  // OpenMesh's mesh).
  const std::size_t cap = oriented.num_vertices() + 100 * std::max<std::size_t>(sites, 1);
  const double feature_angle = co.feature_angle > 0 ? co.feature_angle : options.edge_feature_angle;
  SizingOptions sizing;
  sizing.radians_per_edge = options.edge_sizing_angle * M_PI / 180;
  EdgeRemeshStats edge_stats;
  TriangleMesh edges = remesh_by_edge_operations(oriented, surface, length, feature_angle, options.edge_iterations, cap,
                                                 sites, &edge_stats, sizing.radians_per_edge > 0 ? &sizing : nullptr);
  // The fold check is stricter with a sizing field (two of a vertex's own spacings): where it
  // refuses, one spacing everywhere is tried as without the field (a genus-73 scan's handles at
  // 5,000 vertices: docs/cvt.md, "A sizing field for the edge remesh").
  if (edges.triangles.empty() && sizing.radians_per_edge > 0)
    edges = remesh_by_edge_operations(oriented, surface, length, feature_angle, options.edge_iterations, cap, sites,
                                      &edge_stats);
  if (edges.triangles.empty()) {
    why = "no remesh by edge operations (too many splits, or a fold)";
    return {};
  }
  std::string defect;
  if (!same_topology_per_component(oriented, edges, &defect)) {
    why = "the remesh by edge operations had " + defect;
    return {};
  }
  // Then the CVT dual's post-pass (flips, moves, far-point insertions) against the input: it
  // keeps the topology by construction, and is put back where the check says otherwise.
  TriangleMesh improved = edges;
  std::vector<Index> no_sites(improved.num_vertices(), kInvalidIndex);
  RemeshStats post;
  improve_remesh(improved, no_sites, oriented, bounding_box(oriented).diagonal(), sites, options.remesh, nullptr, post,
                 &surface);
  if (same_topology_per_component(oriented, improved)) edges = std::move(improved), remesh_stats = post;
  remesh_stats.fold_refinements = edge_stats.fold_refinements;
  const MeshQuality q = measure_mesh_quality(edges), input_q = measure_mesh_quality(oriented);
  if (q.min_angle < std::min(kMinAngleDeg, input_q.min_angle)) {
    why = "the remesh by edge operations had a smallest angle of " + fixed2(q.min_angle, " degrees") + ", below the input's";
    return {};
  }
  if (q.below_30 > input_q.below_30) {
    why = "the remesh by edge operations had more angles below 30 degrees than the input (" + fixed2(100 * q.below_30, "%") +
          " against " + fixed2(100 * input_q.below_30, "%") + ")";
    return {};
  }
  min_angle = q.min_angle;
  return edges;
}

}  // namespace

ComponentRemesh remesh_component(const TriangleMesh& input, const CvtOptions& co, const SurfaceRemeshOptions& options,
                                 ComponentReport& rep, bool grow) {
  ComponentRemesh out;
  TriangleMesh oriented = input;
  rep.faces_flipped = orient_by_majority(oriented);
  const std::size_t n = rep.sites;
  try {
    // A remesh by edge operations (empty where edge_operations_remesh's checks refuse it), and
    // taking one as the component's.
    RemeshStats edge_stats;
    double edge_angle = 0;   // the last kept one's smallest angle
    auto edge_remesh = [&](std::string& why) {
      const auto t0 = Clock::now();
      TriangleMesh edges = edge_operations_remesh(oriented, rep.area, n, co, options, edge_stats, why, edge_angle);
      rep.remesh_seconds += seconds_since(t0);
      return edges;
    };
    auto take_edges = [&](TriangleMesh&& edges) {
      rep.by_edge_operations = true;
      out.ok = true;
      out.by_edge_operations = true;
      out.remesh_stats = edge_stats;
      out.vertex_label.assign(input.num_vertices(), kInvalidIndex);
      out.mesh = std::move(edges);
    };
    // RemeshMethod::edges: edge operations first. One below the 20-degree floor is held back
    // while the CVT is tried, and the one with the larger smallest angle is kept (on the corpus
    // at 5,000 vertices the CVT reached the floor on 8 malign files where edge operations did
    // not: docs/cvt.md, "Two methods").
    const bool edges_first = options.method == RemeshMethod::edges;
    TriangleMesh held;
    double held_angle = 0;
    if (edges_first) {
      TriangleMesh edges = edge_remesh(rep.edge_failure);
      if (!edges.triangles.empty()) {
        held_angle = edge_angle;
        if (held_angle >= kMinAngleDeg) {
          take_edges(std::move(edges));
          return out;
        }
        rep.edge_failure = "the remesh by edge operations had a smallest angle of " + fixed2(held_angle, " degrees") +
                           ", below 20 degrees";
        held = std::move(edges);
      }
    }
    CvtOptions c = co;
    c.sites = n;
    c.edge_length = 0;
    c.hopeless_check_iteration = options.hopeless_check_iteration;
    c.hopeless_defects = options.hopeless_defects;
    c.hopeless_fraction = options.hopeless_fraction;
    std::size_t defects = 0;   // of the last attempt (same_topology_per_component)
    // Other initial sites only where a few places went wrong (SurfaceRemeshOptions::retries).
    const std::size_t local_defects = std::max<std::size_t>(1, std::size_t(options.retry_defect_fraction * double(n)));
    RemeshOptions remesh_options = options.remesh;
    if (!remesh_options.accept_dual)
      remesh_options.accept_dual = [&](const TriangleMesh& dual) {
        std::size_t wrong = 0;
        same_topology_per_component(oriented, dual, nullptr, &wrong);
        return wrong <= local_defects;
      };
    auto attempt = [&](CvtResult& cvt, RemeshResult& r, std::string& why) {
      auto t0 = Clock::now();
      cvt = compute_cvt(oriented, c);
      rep.cvt_seconds += seconds_since(t0);
      out.timings += cvt.stats.timings;
      t0 = Clock::now();
      r = restricted_delaunay(cvt, remesh_options);
      rep.remesh_seconds += seconds_since(t0);
      const bool same = same_topology_per_component(oriented, r.mesh, &why, &defects);
      if (!same && cvt.stats.stopped_hopeless)
        why += " (the CVT stopped after " + std::to_string(cvt.stats.iterations) + " Lloyd steps, its dual wrong at " +
               std::to_string(cvt.stats.hopeless_defects) + " places)";
      return same;
    };
    CvtResult cvt;
    RemeshResult r;
    bool ok = attempt(cvt, r, out.why);
    if (!ok && cvt.stats.feature_sites + cvt.stats.cone_sites > 0) {
      // The feature curves' bands leave the closing rounds nothing to add where the dual
      // goes wrong inside them (a junction in a strip between two curves), and a fixed site
      // cannot move off a place where it breaks the dual: the component is remeshed again
      // without its fixed sites rather than kept as it was.
      c.feature_angle = 0;
      c.cone_angle = 0;
      rep.features_dropped = true;
      ok = attempt(cvt, r, out.why);
    }
    for (std::size_t k = 1; !ok && defects <= local_defects && k <= options.retries; ++k) {
      c.seed = co.seed + k;
      ++rep.retries;
      ok = attempt(cvt, r, out.why);
    }
    // A small component (raised to min_component_sites) may be too thin for so few regions
    // (a pin whose regions wrap round it): it gets twice the sites, twice at most, while that
    // stays within its own vertex count (so it never outgrows the input it would be kept as).
    for (int k = 0; !ok && grow && k < 2 && 2 * c.sites <= input.num_vertices(); ++k) {
      c.sites *= 2;
      c.seed = co.seed;
      ++rep.grown;
      ok = attempt(cvt, r, out.why);
    }
    if (!held.triangles.empty()) {
      const double cvt_angle = ok ? measure_mesh_quality(r.mesh).min_angle : 0;
      if (!ok || cvt_angle < held_angle) {
        rep.cvt_failure = ok ? "the CVT's remesh had a smallest angle of " + fixed2(cvt_angle, " degrees") : out.why;
        rep.edge_failure.clear();
        take_edges(std::move(held));
        return out;
      }
    }
    if (!ok && edges_first) out.why += "; " + rep.edge_failure;
    if (!ok && !edges_first && options.edge_operations) {
      std::string why;
      TriangleMesh edges = edge_remesh(why);
      if (!edges.triangles.empty()) {
        rep.cvt_failure = out.why;
        take_edges(std::move(edges));
        return out;
      }
      out.why += "; " + why;
    }
    out.ok = ok;
    if (ok) {
      out.vertex_label = std::move(cvt.vertex_label);
      out.sites = cvt.sites.size();
      out.energy = cvt.energy;
      out.energy_curve = std::move(cvt.energy_curve);
      out.cvt_stats = cvt.stats;
      out.remesh_stats = r.stats;
      out.mesh = std::move(r.mesh);
    }
  } catch (const Error& e) {
    out.error = true;
    out.why = e.what();
  }
  return out;
}

}  // namespace gsp::cvt::detail
