#include "component_budget.hpp"
#include "component_remesh.hpp"
#include "triangle_geometry.hpp"

#include <gsp/batch.hpp>
#include <gsp/cvt/components.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <unordered_map>
#include <utility>

namespace gsp::cvt {

namespace {

void add_stats(CvtStats& sum, const CvtStats& s, bool first) {
  sum.iterations = std::max(sum.iterations, s.iterations);
  sum.rejected_steps += s.rejected_steps;
  sum.initial_sites += s.initial_sites;
  sum.sites_added += s.sites_added;
  sum.sites_relocated += s.sites_relocated;
  sum.split_regions += s.split_regions;
  sum.nondisk_regions += s.nondisk_regions;
  sum.junction_fixes += s.junction_fixes;
  sum.closing_sites += s.closing_sites;
  sum.closing_rounds = std::max(sum.closing_rounds, s.closing_rounds);
  sum.closing_steps = std::max(sum.closing_steps, s.closing_steps);
  sum.feature_sites += s.feature_sites;
  sum.feature_curves += s.feature_curves;
  sum.short_feature_curves += s.short_feature_curves;
  sum.cone_sites += s.cone_sites;
  sum.working_faces += s.working_faces;
  sum.subdivisions = std::max(sum.subdivisions, s.subdivisions);
  sum.bisections += s.bisections;
  sum.planar_flips += s.planar_flips;
  sum.converged = (first || sum.converged) && s.converged;
  sum.update_steps += s.update_steps;
  sum.propagations += s.propagations;
}

void add_stats(RemeshStats& sum, const RemeshStats& s) {
  sum.junctions += s.junctions;
  sum.junctions_over_three += s.junctions_over_three;
  sum.duplicate_triangles += s.duplicate_triangles;
  sum.skipped_junctions += s.skipped_junctions;
  sum.unused_sites += s.unused_sites;
  sum.flips += s.flips;
  sum.smoothing_moves += s.smoothing_moves;
  sum.smoothing_boundary_moves += s.smoothing_boundary_moves;
  sum.boundary_collapses += s.boundary_collapses;
  sum.boundary_splits += s.boundary_splits;
  sum.boundary_snaps += s.boundary_snaps;
  sum.pulls += s.pulls;
  sum.far_point_insertions += s.far_point_insertions;
  sum.far_point_attempts += s.far_point_attempts;
  sum.fold_refinements += s.fold_refinements;
}

// The input's own faces `faces` as a mesh (what a kept component writes: its vertices not
// split, so no two of them share a position).
TriangleMesh input_faces(const TriangleMesh& mesh, const std::vector<Index>& faces) {
  TriangleMesh m;
  std::unordered_map<Index, Index> local;
  for (Index f : faces) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const Index v = mesh.triangles[f][k];
      auto [it, inserted] = local.try_emplace(v, Index(m.positions.size()));
      if (inserted) m.positions.push_back(mesh.positions[v]);
      t[k] = it->second;
    }
    m.triangles.push_back(t);
  }
  return m;
}

// sum[i] += curve[i], both padded with their last value.
void add_curve(std::vector<double>& sum, const std::vector<double>& curve) {
  if (curve.empty()) return;
  const double sum_last = sum.empty() ? 0.0 : sum.back();
  const std::size_t n = std::max(sum.size(), curve.size());
  sum.resize(n, sum_last);
  for (std::size_t i = 0; i < n; ++i) sum[i] += curve[std::min(i, curve.size() - 1)];
}

void append(TriangleMesh& out, const TriangleMesh& piece) {
  const Index offset = Index(out.positions.size());
  out.positions.insert(out.positions.end(), piece.positions.begin(), piece.positions.end());
  for (const Triangle& t : piece.triangles) out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

// The component's sites: its share of the budget by area, or the count of an equilateral
// triangulation of its area at the edge length (compute_cvt's conversion).
std::size_t component_sites(const CvtOptions& o, double area, double total_area) {
  if (o.sites > 0) return std::size_t(std::llround(double(o.sites) * area / total_area));
  return std::size_t(std::llround(2.0 * area / (std::sqrt(3.0) * o.edge_length * o.edge_length)));
}

// Issue 22's quality floor (degrees): a component too small for its share of the budget is
// remeshed with min_component_sites to reach it (one of fewer vertices only where its own
// angles do not), and its remesh is kept where it reaches it, even if the input's angles were
// larger.
constexpr double kSmallComponentAngle = 20.0;

double min_angle_deg(const TriangleMesh& m) { return detail::mesh_min_angle(m) * 180.0 / M_PI; }

std::string degrees(double a) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g deg", a);
  return buf;
}

}  // namespace

const char* outcome_name(ComponentOutcome o) {
  switch (o) {
    case ComponentOutcome::remeshed: return "remeshed";
    case ComponentOutcome::kept_small: return "kept_small";
    case ComponentOutcome::kept_nonmanifold: return "kept_nonmanifold";
    case ComponentOutcome::kept_nonorientable: return "kept_nonorientable";
    case ComponentOutcome::kept_topology: return "kept_topology";
    case ComponentOutcome::kept_error: return "kept_error";
  }
  return "?";
}

const char* method_name(RemeshMethod m) { return m == RemeshMethod::edges ? "edges" : "cvt"; }

RemeshMethod remesh_method(const std::string& name) {
  if (name == "cvt") return RemeshMethod::cvt;
  if (name == "edges") return RemeshMethod::edges;
  throw InvalidInput("remesh method must be 'cvt' or 'edges', not '" + name + "'");
}

std::size_t SurfaceRemeshResult::remeshed() const {
  return std::size_t(std::count_if(components.begin(), components.end(),
                                   [](const ComponentReport& c) { return c.outcome == ComponentOutcome::remeshed; }));
}

std::vector<std::string> kept_components(const SurfaceRemeshResult& r) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < r.components.size(); ++i) {
    const ComponentReport& c = r.components[i];
    if (c.outcome == ComponentOutcome::remeshed) continue;
    lines.push_back("component " + std::to_string(i) + " (" + std::to_string(c.input_faces) + " faces): " + c.reason);
  }
  return lines;
}

SurfaceRemeshResult remesh_surface(const TriangleMesh& mesh, const SurfaceRemeshOptions& options) {
  validate(mesh);
  const CvtOptions& co = options.cvt;
  if ((co.sites > 0) == (co.edge_length > 0)) throw InvalidInput("cvt: give exactly one of sites and edge_length");
  if (co.edge_length > 0 && !std::isfinite(co.edge_length)) throw InvalidInput("cvt: the edge length must be finite");
  if (!(options.retry_defect_fraction >= 0))
    throw InvalidInput("cvt: the retries' defect fraction must be 0 or more");
  if (!(options.edge_sizing_angle >= 0 && options.edge_sizing_angle <= 180))
    throw InvalidInput("cvt: the sizing angle must be in [0, 180] degrees");
  // The surface the input describes (described_surface): its seams closed, each face once, and
  // one vertex per fan where fans touch at a vertex.
  const VertexStitch seams = stitch_boundary_vertices(mesh);
  const FaceCleanup clean = drop_duplicate_faces(seams.mesh);
  const VertexSplit fans = split_nonmanifold_vertices(clean.mesh);
  const ComponentSplit split = split_components(fans.mesh);
  std::vector<ComponentTopology> topology;
  double total_area = 0;
  for (const TriangleMesh& c : split.meshes) {
    topology.push_back(component_topology(c));
    total_area += topology.back().area;
  }
  if (!(total_area > 0)) throw InvalidInput("cvt: the mesh has no area");

  SurfaceRemeshResult out;
  out.area = total_area;
  out.vertices_split = fans.split;
  out.boundary_vertices_stitched = seams.stitched;
  out.duplicate_faces_removed = clean.duplicate_faces;
  out.repeated_vertex_faces_removed = clean.repeated_vertex_faces;
  std::vector<Index> label(seams.mesh.num_vertices(), kInvalidIndex);   // per stitched vertex

  // What each component gets: kept as it is for a reason known before any CVT, or remeshed.
  const std::size_t nc = split.meshes.size();
  std::vector<ComponentReport> reports(nc);
  std::vector<std::size_t> todo;   // the components to remesh
  std::vector<bool> planned(nc, false), raised(nc, false);
  std::vector<std::size_t> candidates;   // manifold and orientable: remeshed unless too small
  std::vector<detail::ComponentBudgetItem> items;
  for (std::size_t ci = 0; ci < nc; ++ci) {
    const TopologyReport& t = topology[ci].report;
    ComponentReport& rep = reports[ci];
    rep.input_vertices = split.meshes[ci].num_vertices();
    rep.input_faces = split.meshes[ci].num_faces();
    rep.area = topology[ci].area;
    rep.euler_characteristic = t.euler_characteristic;
    rep.boundary_loops = t.boundary_loops;
    if (!t.is_manifold()) {
      rep.outcome = ComponentOutcome::kept_nonmanifold;
      rep.reason = std::to_string(t.nonmanifold_edges) + " non-manifold edges, " +
                   std::to_string(t.nonmanifold_vertices) + " non-manifold vertices";
    } else if (!topology[ci].orientable) {
      rep.outcome = ComponentOutcome::kept_nonorientable;
      rep.reason = "its faces cannot be oriented alike";
    } else {
      candidates.push_back(ci);
      const std::size_t share = component_sites(co, rep.area, total_area);
      const bool tiny = share < options.min_component_sites && rep.input_vertices < options.min_component_sites;
      items.push_back({share, rep.input_vertices, rep.area, tiny && min_angle_deg(split.meshes[ci]) >= kSmallComponentAngle});
    }
  }
  const std::vector<std::size_t> sites = detail::plan_component_sites(
      items, options.min_component_sites, options.max_small_raise_fraction);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::size_t ci = candidates[k];
    ComponentReport& rep = reports[ci];
    if (sites[k] == 0) {
      rep.outcome = ComponentOutcome::kept_small;
      rep.reason = "its share of the budget is " + std::to_string(items[k].share) + " sites (fewer than " +
                   std::to_string(options.min_component_sites) + "), it has " + std::to_string(rep.input_vertices) +
                   " vertices and " +
                   (items[k].well_shaped ? "no angle below " + degrees(kSmallComponentAngle)
                                         : std::string("the budget's room for small components is taken"));
    } else {
      rep.sites = sites[k];
      raised[ci] = items[k].share < options.min_component_sites;
      todo.push_back(ci);
      planned[ci] = true;
    }
  }

  // The remeshes, each component on its own (they share nothing but the options), so several
  // at once on several cores, the largest first; put together in component order below, so
  // the output is the same whatever ran where.
  std::vector<detail::ComponentRemesh> remeshes(nc);
  std::stable_sort(todo.begin(), todo.end(), [&](std::size_t a, std::size_t b) { return reports[a].sites > reports[b].sites; });
  std::size_t budget = 0;
  for (std::size_t ci : todo) budget += reports[ci].sites;
  // One component with most of the budget runs alone, its propagations on all the cores.
  const bool dominated = !todo.empty() && 4 * reports[todo.front()].sites > 3 * budget;
  const unsigned threads = co.threads == 1 || dominated ? 1u : resolve_threads(co.threads, todo.size());
  std::mutex progress_mutex;   // the caller's callback is called from one thread at a time
  CvtOptions shared = co;
  if (threads > 1) shared.threads = 1;   // the cores are taken by the components (and then each is as on one thread)
  if (threads > 1 && co.on_iteration)
    shared.on_iteration = [&](const IterationInfo& info) {
      const std::lock_guard<std::mutex> lock(progress_mutex);
      co.on_iteration(info);
    };
  parallel_for(todo.size(), threads, [&](std::size_t j) {
    const std::size_t ci = todo[j];
    remeshes[ci] = detail::remesh_component(split.meshes[ci], shared, options, reports[ci], raised[ci]);
  });

  std::vector<TriangleMesh> kept;
  bool first = true;
  for (std::size_t ci = 0; ci < nc; ++ci) {
    ComponentReport& rep = reports[ci];
    const TriangleMesh& input = split.meshes[ci];
    detail::ComponentRemesh& r = remeshes[ci];
    auto keep = [&](ComponentOutcome why, std::string reason) {
      rep.outcome = why;
      rep.reason = std::move(reason);
      rep.output_vertices = input.num_vertices();
      rep.output_faces = input.num_faces();
      kept.push_back(input_faces(clean.mesh, split.face_ids[ci]));
    };
    if (!planned[ci]) {
      keep(rep.outcome, rep.reason);
    } else if (r.error) {
      keep(ComponentOutcome::kept_error, r.why);
    } else {
      // Every attempt's time, whether the component ends remeshed or kept.
      out.remesh_seconds += rep.remesh_seconds;
      out.cvt_stats.timings += r.timings;
      double remeshed_angle = 0, input_angle = 0;
      if (!r.ok) {
        keep(ComponentOutcome::kept_topology,
             "the remesh had " + r.why +
                 (rep.retries ? " (and " + std::to_string(rep.retries) + " more from other initial sites)" : ""));
      } else if (raised[ci] && (remeshed_angle = min_angle_deg(r.mesh)) < kSmallComponentAngle &&
                 remeshed_angle < (input_angle = min_angle_deg(input))) {
        // Raised above its share, a small component's remesh is kept where its angles are
        // good (fewer vertices than the input's) or at least better than the input's.
        keep(ComponentOutcome::kept_small, "its share of the budget is below " +
                                               std::to_string(options.min_component_sites) +
                                               " sites and its remesh's smallest angle (" + degrees(remeshed_angle) +
                                               ") was below its own (" + degrees(input_angle) + ")");
      } else {
        for (std::size_t v = 0; v < input.num_vertices(); ++v)
          if (r.vertex_label[v] != kInvalidIndex)
            label[fans.vertex_source[split.vertex_ids[ci][v]]] = Index(out.sites + r.vertex_label[v]);
        add_stats(out.remesh_stats, r.remesh_stats);
        if (!r.by_edge_operations) {   // a remesh by edge operations has no regions and no energy
          out.sites += r.sites;
          out.energy += r.energy;
          add_curve(out.energy_curve, r.energy_curve);
          add_stats(out.cvt_stats, r.cvt_stats, first);
          first = false;
        }
        rep.output_vertices = r.mesh.num_vertices();
        rep.output_faces = r.mesh.num_faces();
        append(out.mesh, r.mesh);
      }
    }
    r = detail::ComponentRemesh();
    out.components.push_back(std::move(rep));
  }
  for (const TriangleMesh& k : kept) append(out.mesh, k);
  out.vertex_label.resize(mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) out.vertex_label[v] = label[seams.vertex_map[v]];
  return out;
}

}  // namespace gsp::cvt
