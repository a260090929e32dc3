#include "component_remesh.hpp"

#include <gsp/cvt/components.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <chrono>
#include <utility>

namespace gsp::cvt::detail {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Orients the component alike, keeping the orientation most of its faces had (so a mesh with
// a few flipped faces keeps its normals). Returns the faces whose orientation changed.
std::size_t orient_by_majority(TriangleMesh& m) {
  const std::int64_t flipped = orient_consistently(m);
  if (2 * std::size_t(flipped) <= m.num_faces()) return std::size_t(flipped);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m.num_faces() - std::size_t(flipped);
}

}  // namespace

ComponentRemesh remesh_component(const TriangleMesh& input, const CvtOptions& co, const SurfaceRemeshOptions& options,
                                 ComponentReport& rep, bool grow) {
  ComponentRemesh out;
  TriangleMesh oriented = input;
  rep.faces_flipped = orient_by_majority(oriented);
  const std::size_t n = rep.sites;
  try {
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
    if (!ok && c.feature_angle > 0 && cvt.stats.feature_sites > 0) {
      // The feature curves' bands leave the closing rounds nothing to add where the dual
      // goes wrong inside them (a junction in a strip between two curves): the component
      // is remeshed again without its features rather than kept as it was.
      c.feature_angle = 0;
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
