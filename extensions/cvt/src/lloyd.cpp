// Lloyd iterations for a geodesic CVT: propagate from all sites (GSP, labels), move every site
// to its region's centroid projected back onto the region, keep the step only if the energy
// went down. See docs/cvt.md for the choices made here.
#include "boundary_loops.hpp"
#include "child_faces.hpp"
#include "feature_sites.hpp"
#include "input_walk.hpp"
#include "junctions.hpp"
#include "regions.hpp"
#include "working_flips.hpp"
#include "working_geometry.hpp"

#include <gsp/cvt/components.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/available_memory.hpp>
#include <gsp/errors.hpp>
#include <gsp/sampling/sampler.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numeric>

namespace gsp::cvt {

namespace {

using namespace detail;
using Clock = std::chrono::steady_clock;

// Width of the band around feature curves that belongs to their samples, in site spacings:
// about where the regions of the first row of free sites would begin anyway (half the distance
// to a row of sites 0.87 spacings off the curve), so the band claims little that the Voronoi
// regions would not have given it, and a strip narrower than 0.8 spacings has no free site.
constexpr double kFeatureBand = 0.4;
// Peak bytes of a CVT run per working-mesh face (the working mesh, GSP's solver and query
// state, labels, the dual), for the memory check before the working mesh is built: measured
// 578-627 on spot at 370k-1.5M working faces (gsp-cvt --stats, memory.peak_bytes).
constexpr double kBytesPerWorkingFace = 650;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

struct Evaluation {
  GeodesicResult result;
  std::vector<Index> label;   // per face, after small detached pieces were absorbed
  Components components;      // of `label`
  Buckets buckets;            // faces per site, of `label`
  double energy = 0;
};

class Lloyd {
 public:
  Lloyd(const WorkingGeometry& g, const GeodesicSolver& solver, const CvtOptions& o, CvtStats& stats)
      : g_(g), solver_(solver), o_(o), stats_(stats) {}

  Evaluation evaluate(const std::vector<SurfaceSite>& sites) {
    auto t0 = Clock::now();
    std::vector<Source> sources;
    sources.reserve(sites.size());
    for (const SurfaceSite& s : sites) sources.push_back(Source::at(s.point));
    GeodesicOptions go;
    go.want_face_sources = true;
    go.threads = o_.threads;
    Evaluation e;
    e.result = solver_.compute(sources, go);
    stats_.propagations++;
    stats_.update_steps += e.result.stats.update_steps;
    stats_.timings.propagate += seconds_since(t0);
    t0 = Clock::now();
    e.energy = cvt_energy(g_.mesh, e.result);
    e.label = e.result.face_source;
    if (features_) claim_feature_band(*features_, e.label);
    const std::vector<Index> site_face = faces_of(sites);
    // Pieces of a region a few faces large are artefacts of face-granular labels (a face whose
    // centroid is barely on the other side): they take their neighbours' label.
    Components c = find_components(g_, e.label, site_face, sites.size());
    if (absorb_small_components(g_, e.label, c, min_piece_area(sites.size())) > 0)
      c = find_components(g_, e.label, site_face, sites.size());
    e.components = std::move(c);
    e.buckets = bucket_faces(e.label, sites.size());
    stats_.timings.centroids += seconds_since(t0);
    return e;
  }

  // Where each site moves: its main component's area centroid, t of the way from the site,
  // projected onto that component (or onto its boundary arc for boundary sites).
  std::vector<SurfaceSite> step(const Evaluation& e, const std::vector<SurfaceSite>& sites, double t,
                                bool keep_boundary_state) const {
    std::vector<SurfaceSite> out(sites.size());
    for (Index s = 0; s < sites.size(); ++s) {
      const Index k = e.components.main[s];
      if (sites[s].fixed) {
        out[s] = sites[s];
        continue;
      }
      if (k == kInvalidIndex || !(e.components.area[k] > 0)) {
        out[s] = sites[s];   // lost its region: fix_regions relocates it
        continue;
      }
      const Vec3 c = (1.0 / e.components.area[k]) * e.components.moment[k];
      const Vec3 target = sites[s].position + t * (c - sites[s].position);
      bool boundary = o_.boundary_sites && touches_boundary(e, s, k);
      if (keep_boundary_state) boundary = boundary && sites[s].on_boundary;
      out[s] = project(e, s, k, target, boundary);
      if (out[s].point.element == kInvalidIndex) out[s] = sites[s];
    }
    return out;
  }

  // Detached parts, regions that are not disks, boundary loops with fewer than three regions
  // or a region met twice along them, sites without a region. Returns true if sites changed.
  bool fix(const Evaluation& e, std::vector<SurfaceSite>& sites) {
    const auto t0 = Clock::now();
    const Components& c = e.components;
    const std::size_t n = sites.size();
    std::vector<SurfaceSite> added;
    std::vector<bool> flagged(n, false);
    const std::vector<long> chi = component_euler(g_, c);
    for (Index k = 0; k < c.label.size(); ++k) {
      const Index s = c.label[k];
      if (c.main[s] != k) {   // a detached part large enough to survive absorption
        stats_.split_regions++;
        if (flagged[s]) continue;
        flagged[s] = true;
        added.push_back(closest_in_component(e, k, (1.0 / c.area[k]) * c.moment[k]));
      } else if (chi[k] <= 0 && !flagged[s]) {   // one piece, but an annulus or worse
        stats_.nondisk_regions++;
        flagged[s] = true;
        added.push_back(farthest_in_component(e, k));
      }
    }
    fix_boundary(e, flagged, added);
    fix_junctions(e, sites, added);
    // Sites that lost their whole region (another site took their face): to the farthest points.
    std::vector<Index> lost;
    for (Index s = 0; s < n; ++s)
      if (c.main[s] == kInvalidIndex && !sites[s].fixed) lost.push_back(s);
    if (!lost.empty()) {
      std::vector<Index> order(g_.mesh.num_faces());
      std::iota(order.begin(), order.end(), Index(0));
      const auto& d = e.result.face_distance;
      std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        const double da = std::isfinite(d[a]) ? d[a] : -1, db = std::isfinite(d[b]) ? d[b] : -1;
        return da > db;
      });
      const double spacing = std::sqrt(g_.total_area / double(n));
      std::vector<Vec3> taken;
      std::size_t next = 0;
      for (Index s : lost) {
        while (next < order.size()) {
          const Index f = order[next++];
          if (!(g_.area[f] > 0)) continue;
          bool near = false;
          for (const Vec3& p : taken) near = near || distance(p, g_.centroid[f]) < spacing;
          if (near) continue;
          sites[s] = g_.at(f, {1.0 / 3, 1.0 / 3, 1.0 / 3});
          taken.push_back(sites[s].position);
          stats_.sites_relocated++;
          break;
        }
      }
    }
    // At most max_added_fraction * N sites in all: on CAD meshes (creases, slivers, thin
    // walls) the fixes would otherwise keep finding regions to split.
    const std::size_t cap = std::size_t(o_.max_added_fraction * double(stats_.initial_sites));
    added.resize(append_capped(added, sites, stats_.sites_added, cap));
    stats_.timings.fix += seconds_since(t0);
    return !added.empty() || !lost.empty();
  }

  // After the iterations, while the dual does not have the input's topology: a new site at
  // each place fix_junctions finds, without a Lloyd step after it (a step moves the new site
  // off the junction it resolves; docs/cvt.md). Its own cap, `cap` sites in all. Returns true
  // if sites were added.
  bool close_dual(const Evaluation& e, std::vector<SurfaceSite>& sites, std::size_t cap) {
    const auto t0 = Clock::now();
    std::vector<SurfaceSite> added;
    fix_junctions(e, sites, added);
    const std::size_t kept = append_capped(added, sites, stats_.closing_sites, cap);
    stats_.timings.fix += seconds_since(t0);
    return kept > 0;
  }

  // True when the dual of these regions (before the remesh's post-pass, which keeps its
  // topology) is a manifold with the topology of `input`, component by component.
  bool dual_has_topology(const Evaluation& e, const std::vector<SurfaceSite>& sites, const TriangleMesh& input) const {
    return same_topology_per_component(input, dual_mesh(e, sites));
  }

  // How many places of the dual are wrong (0: it has the input's topology).
  std::size_t dual_defects(const Evaluation& e, const std::vector<SurfaceSite>& sites, const TriangleMesh& input) const {
    std::size_t defects = 0;
    if (same_topology_per_component(input, dual_mesh(e, sites), nullptr, &defects)) return 0;
    return std::max<std::size_t>(defects, 1);
  }

  // The dual of the regions as a mesh of the sites it uses.
  TriangleMesh dual_mesh(const Evaluation& e, const std::vector<SurfaceSite>& sites) const {
    std::vector<Vec3> positions(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) positions[i] = sites[i].position;
    const DualTriangles d = dual_triangles(g_.mesh, g_.conn, e.label, positions);
    TriangleMesh dual;
    std::vector<Index> local(sites.size(), kInvalidIndex);
    for (const Triangle& t : d.triangles) {
      Triangle u;
      for (int k = 0; k < 3; ++k) {
        if (local[t[k]] == kInvalidIndex) {
          local[t[k]] = Index(dual.positions.size());
          dual.positions.push_back(positions[t[k]]);
        }
        u[k] = local[t[k]];
      }
      dual.triangles.push_back(u);
    }
    return dual;
  }

  // Sites whose region touches the boundary, moved onto it (before the first Lloyd step).
  std::vector<SurfaceSite> snap_to_boundary(const Evaluation& e, const std::vector<SurfaceSite>& sites) const {
    std::vector<SurfaceSite> out = sites;
    for (Index s = 0; s < sites.size(); ++s) {
      const Index k = e.components.main[s];
      if (sites[s].fixed || k == kInvalidIndex || !touches_boundary(e, s, k)) continue;
      const SurfaceSite q = project(e, s, k, sites[s].position, true);
      if (q.point.element != kInvalidIndex) out[s] = q;
    }
    return out;
  }

 private:
  double min_piece_area(std::size_t sites) const { return 0.2 * g_.total_area / double(std::max<std::size_t>(sites, 1)); }

  // The valid sites of `added` appended to `sites` while `counter` (counted up) is below
  // `cap`; returns how many were appended.
  static std::size_t append_capped(const std::vector<SurfaceSite>& added, std::vector<SurfaceSite>& sites,
                                   std::size_t& counter, std::size_t cap) {
    std::size_t kept = 0;
    for (const SurfaceSite& s : added) {
      if (s.point.element == kInvalidIndex || counter >= cap) continue;
      sites.push_back(s);
      ++counter;
      ++kept;
    }
    return kept;
  }

  static std::vector<Index> faces_of(const std::vector<SurfaceSite>& sites) {
    std::vector<Index> f(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) f[i] = sites[i].point.element;
    return f;
  }

  bool touches_boundary(const Evaluation& e, Index s, Index k) const {
    for (Index i = e.buckets.begin[s]; i < e.buckets.begin[s + 1]; ++i) {
      const Index f = e.buckets.faces[i];
      if (e.components.of_face[f] != k) continue;
      for (Index j = 0; j < 3; ++j)
        if (g_.boundary_halfedge[3 * f + j]) return true;
    }
    return false;
  }

  // The point of component k (or of its boundary arc) closest to p; a site with no face when
  // there is none (the callers keep the old site then). A face whose sphere around its
  // centroid lies farther from p than the best point so far cannot hold a closer one: skipped
  // without its closest point (the relative slack covers rounding, so the answer is the same).
  SurfaceSite project(const Evaluation& e, Index s, Index k, Vec3 p, bool boundary) const {
    SurfaceSite best;
    double best_d = std::numeric_limits<double>::infinity();
    for (Index i = e.buckets.begin[s]; i < e.buckets.begin[s + 1]; ++i) {
      const Index f = e.buckets.faces[i];
      if (e.components.of_face[f] != k) continue;
      if (distance(p, g_.centroid[f]) > (best_d + g_.radius[f]) * (1 + 1e-12)) continue;
      for (Index j = 0; j < (boundary ? 3u : 1u); ++j) {
        if (boundary && !g_.boundary_halfedge[3 * f + j]) continue;
        const SurfaceSite q = boundary ? g_.closest_on_halfedge(3 * f + j, p) : g_.closest_on_face(f, p);
        const double d = distance(q.position, p);
        if (d < best_d) best_d = d, best = q;
      }
    }
    return best;
  }

  SurfaceSite closest_in_component(const Evaluation& e, Index k, Vec3 p) const {
    const Index s = e.components.label[k];
    return project(e, s, k, p, false);
  }

  SurfaceSite farthest_in_component(const Evaluation& e, Index k) const {
    const Index s = e.components.label[k];
    Index best = kInvalidIndex;
    for (Index i = e.buckets.begin[s]; i < e.buckets.begin[s + 1]; ++i) {
      const Index f = e.buckets.faces[i];
      if (e.components.of_face[f] != k || !(g_.area[f] > 0)) continue;
      if (best == kInvalidIndex || e.result.face_distance[f] > e.result.face_distance[best]) best = f;
    }
    if (best == kInvalidIndex) return {};   // no face with area: the caller skips it
    return g_.at(best, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  }

  void fix_boundary(const Evaluation& e, std::vector<bool>& flagged, std::vector<SurfaceSite>& added) {
    std::map<Index, int> runs;   // label -> runs along all loops
    std::map<Index, Index> second_run_halfedge;
    for (const std::vector<Index>& loop : loops_) {
      std::vector<std::pair<Index, std::size_t>> seq;   // (label, first position) per run
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Index l = e.label[face_of(loop[i])];
        if (seq.empty() || seq.back().first != l) seq.push_back({l, i});
      }
      if (seq.size() > 1 && seq.front().first == seq.back().first) seq.pop_back();   // cyclic
      std::vector<Index> distinct;
      for (auto& [l, i] : seq) distinct.push_back(l);
      std::sort(distinct.begin(), distinct.end());
      distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
      if (distinct.size() < 3 && loop.size() >= 3) {
        // A hole with fewer than three regions around it has no triangle in the dual: spread
        // sites along it.
        for (std::size_t part : {loop.size() / 3, 2 * loop.size() / 3}) {
          SurfaceSite s = g_.closest_on_halfedge(loop[part], g_.mesh.positions[from_vertex(g_.mesh, loop[part])]);
          added.push_back(s);
        }
        continue;
      }
      for (std::size_t r = 0; r < seq.size(); ++r) {
        const Index l = seq[r].first;
        if (l == kInvalidIndex || is_fixed(l)) continue;
        if (++runs[l] == 2) {
          const std::size_t end = r + 1 < seq.size() ? seq[r + 1].second : loop.size();
          second_run_halfedge[l] = loop[(seq[r].second + end) / 2];
        }
      }
    }
    for (auto& [l, h] : second_run_halfedge) {
      if (flagged[l]) continue;
      flagged[l] = true;
      stats_.split_regions++;
      added.push_back(g_.closest_on_halfedge(h, 0.5 * (g_.mesh.positions[from_vertex(g_.mesh, h)] +
                                                      g_.mesh.positions[to_vertex(g_.mesh, h)])));
    }
  }

  // Where the dual would not be a manifold (the same three regions meeting twice, a region met
  // twice around a vertex, two regions whose border has more than two ends): a new site at
  // that vertex splits the region that causes it.
  void fix_junctions(const Evaluation& e, const std::vector<SurfaceSite>& sites, std::vector<SurfaceSite>& added) {
    std::vector<Vec3> positions(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) positions[i] = sites[i].position;
    const DualTriangles d = dual_triangles(g_.mesh, g_.conn, e.label, positions);
    std::vector<Index> vertices = d.trouble_vertices;
    for (Index v : overused_edge_vertices(d)) vertices.push_back(v);
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    const double spacing = 0.5 * std::sqrt(g_.total_area / double(std::max<std::size_t>(e.buckets.begin.size() - 1, 1)));
    std::vector<Vec3> placed;
    for (Index v : vertices) {
      const Vec3 p = g_.mesh.positions[v];
      bool near = false;
      for (const Vec3& q : placed) near = near || distance(p, q) < spacing;
      for (const SurfaceSite& q : added) near = near || distance(p, q.position) < spacing;
      if (near) continue;
      const Index corner = g_.conn.vertex_corners[g_.conn.vertex_corner_begin[v]];
      std::array<double, 3> bary{0, 0, 0};
      bary[corner_of(corner)] = 1;
      added.push_back(g_.at(face_of(corner), bary));
      placed.push_back(p);
      stats_.junction_fixes++;
    }
  }

 public:
  std::vector<std::vector<Index>> loops_;
  const FeatureSites* features_ = nullptr;   // its sites are sites [0, size)

 private:
  bool is_fixed(Index label) const { return features_ && label < features_->sites.size(); }

  const WorkingGeometry& g_;
  const GeodesicSolver& solver_;
  const CvtOptions& o_;
  CvtStats& stats_;
};

std::size_t site_count(const CvtOptions& o, double area) {
  if ((o.sites > 0) == (o.edge_length > 0)) throw InvalidInput("cvt: give exactly one of sites and edge_length");
  if (o.sites > 0) return o.sites;
  if (!std::isfinite(o.edge_length)) throw InvalidInput("cvt: the edge length must be finite");
  const double n = 2.0 * area / (std::sqrt(3.0) * o.edge_length * o.edge_length);
  return std::max<std::size_t>(4, std::size_t(std::llround(n)));
}

// `walk`: given when the working mesh was flipped in planes; a site in a flipped face can lie
// in another input face of its parent's plane, found by walking there.
Site to_input(const WorkingMesh& w, const SurfaceSite& s, const detail::InputWalk* walk) {
  Site out;
  const Index f = s.point.element;
  out.point = SurfacePoint::in_face(w.parent[f], {0, 0, 0});
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) out.point.barycentric[j] += s.point.barycentric[k] * w.corner_bary[f][k][j];
  const auto& b = out.point.barycentric;
  if (walk && std::min({b[0], b[1], b[2]}) < -1e-9) {
    const auto [face, bary] = walk->locate(w.parent[f], s.position, true);
    out.point = SurfacePoint::in_face(face, bary);
  }
  out.position = s.position;
  out.on_boundary = s.on_boundary;
  out.fixed = s.fixed;
  return out;
}

// Initial sites. Poisson-disk sampling runs on the input mesh (its radius search costs a few
// sampling runs, 4^levels times cheaper there than on the working mesh) and each sample is
// found again among the working faces of its input face. Farthest-point sampling picks vertices, so it runs
// on the working mesh when the input has too few.
std::vector<SurfaceSite> initial_sites(const TriangleMesh& mesh, const WorkingMesh& w, const WorkingGeometry& g,
                                       std::size_t n, const CvtOptions& o) {
  sampling::SamplingOptions so;
  so.mode = o.initial == InitialSites::farthest ? sampling::Mode::farthest : sampling::Mode::poisson;
  so.count = n;
  so.seed = o.seed;
  so.count_tolerance = 0.02;
  std::vector<SurfaceSite> sites;
  const sampling::AreaSampler uniform(w.mesh);
  sampling::Random random(o.seed ^ 0x5eed5eedULL);
  if (o.initial == InitialSites::random) {
    while (sites.size() < n) {
      const sampling::Sample s = uniform.draw(w.mesh, random);
      sites.push_back(g.at(s.point.element, s.point.barycentric));
    }
    return sites;
  }
  const bool on_input = so.mode == sampling::Mode::poisson || n <= mesh.num_vertices() / 2;
  if (!on_input) {
    const sampling::Sampler sampler(w.mesh);
    for (const sampling::Sample& s : sampler.sample(so).samples) sites.push_back(g.at(s.point.element, s.point.barycentric));
    return sites;
  }
  const sampling::Sampler sampler(mesh);
  const ChildFaces children(w, mesh.num_faces());
  // After planar flips an input face can be left without working faces of its own (none has
  // its centroid there): its samples are found by walking the working mesh from a face at the
  // input face's first corner (the working mesh's first vertices are the input's).
  std::unique_ptr<detail::InputWalk> working_walk;
  std::vector<Index> face_at_vertex;
  for (const sampling::Sample& s : sampler.sample(so).samples) {
    SurfaceSite site = children.closest(g, s.point.element, s.point.barycentric, s.position);
    if (site.point.element == kInvalidIndex) {
      if (!working_walk) {
        working_walk = std::make_unique<detail::InputWalk>(w.mesh);
        face_at_vertex.assign(w.mesh.num_vertices(), kInvalidIndex);
        for (Index f = 0; f < w.mesh.num_faces(); ++f)
          for (Index v : w.mesh.triangles[f]) face_at_vertex[v] = f;
      }
      const Index start = face_at_vertex[mesh.triangles[s.point.element][0]];
      if (start == kInvalidIndex) continue;
      const auto [face, bary] = working_walk->locate(start, s.position, true);
      site = g.at(face, bary);
    }
    sites.push_back(site);
  }
  // The radius search meets the count within 2%: trim the last accepted samples (the vertex
  // fill, which plugs the smallest gaps) or add area-uniform points; Lloyd evens both out.
  if (sites.size() > n) sites.resize(n);
  while (sites.size() < n) {
    const sampling::Sample s = uniform.draw(w.mesh, random);
    sites.push_back(g.at(s.point.element, s.point.barycentric));
  }
  return sites;
}

}  // namespace

CvtResult compute_cvt(const TriangleMesh& mesh, const CvtOptions& options) {
  validate(mesh);
  if (options.max_iterations < 0) throw InvalidInput("cvt: negative iteration cap");
  if (options.hopeless_check_iteration < 0 || !(options.hopeless_fraction >= 0) || !std::isfinite(options.hopeless_fraction))
    throw InvalidInput("cvt: the hopeless check needs an iteration >= 0 and a fraction >= 0");
  if (!(options.tolerance >= 0)) throw InvalidInput("cvt: the tolerance must be >= 0");
  if (!(options.over_relaxation >= 1.0 && options.over_relaxation < 2.0))
    throw InvalidInput("cvt: the over-relaxation factor must be in [1, 2)");
  if (!(options.feature_angle >= 0 && options.feature_angle <= 180))
    throw InvalidInput("cvt: the feature angle must be in [0, 180] degrees");
  if (!(options.cone_angle >= 0 && options.cone_angle <= 360))
    throw InvalidInput("cvt: the spike tips' angle must be in [0, 360] degrees");
  CvtResult out;
  CvtStats& stats = out.stats;
  auto t0 = Clock::now();
  double area = 0;
  for (const Triangle& t : mesh.triangles)
    area += 0.5 * norm(cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]));
  if (!(area > 0)) throw InvalidInput("cvt: the mesh has no area");
  const std::size_t n = site_count(options, area);
  // Uniform 1-to-4 levels until the working mesh has min_faces_per_site faces per site.
  auto levels_for = [&](std::size_t faces) {
    int l = 0;
    while (l < options.max_subdivisions && double(faces) * std::pow(4.0, l) < double(options.min_faces_per_site) * double(n))
      ++l;
    return l;
  };
  int levels = levels_for(mesh.num_faces());
  // Too many sites for the split mesh even with every edge counted apart (E <= 3F): say so
  // before splitting, which at 10 levels of a large input would take long.
  const double k = std::pow(2.0, levels) - 1;
  const double vertex_bound = double(mesh.num_vertices()) + 3.0 * double(mesh.num_faces()) * k +
                              double(mesh.num_faces()) * k * (k - 1) / 2;
  if (double(n) > vertex_bound)
    throw InvalidInput("cvt: " + std::to_string(n) + " sites asked for, the mesh (split " + std::to_string(levels) +
                       " times) has at most " + std::to_string(std::size_t(vertex_bound)) + " vertices");
  // Faces longer than half the site spacing could hold two sites: bisect them. First on the
  // input, to the length that the uniform levels will halve down to the bound (split uniformly
  // first, every sliver of a CAD export would become four slivers to bisect, and the bounded
  // bisection ran out with a third of the working faces still too long); the levels are
  // chosen again for the faces the bisection made. Then on the split mesh, for what is left.
  // Bounded, so that a degenerate input cannot blow up.
  const double max_edge = 0.5 * std::sqrt(area / double(n));
  out.working = subdivide(mesh, 0);
  const std::size_t input_cap = mesh.num_faces() + 4 * std::size_t(options.min_faces_per_site) * n;
  for (int round = 0; round < 4; ++round) {
    stats.bisections += refine_long_edges(out.working, max_edge * std::pow(2.0, levels), input_cap);
    const int again = levels_for(out.working.mesh.num_faces());
    if (again == levels) break;
    levels = again;
  }
  // Fewer levels than the last round bisected for (nothing to do when the rounds settled).
  stats.bisections += refine_long_edges(out.working, max_edge * std::pow(2.0, levels), input_cap);
  // A working mesh the machine cannot hold is refused before it is built (gsp/available_memory.hpp).
  const double planned_faces = double(out.working.mesh.num_faces()) * std::pow(4.0, levels) + 4.0 * double(n);
  char what[120];
  std::snprintf(what, sizeof what, "cvt: %zu sites need a working mesh of about %.3g faces", n, planned_faces);
  require_memory(what, planned_faces * kBytesPerWorkingFace, "vertices", options.max_memory);
  // Slivers in planes (CAD fans) made well-shaped before the split multiplies them
  // (working_flips.hpp); the split keeps their shapes.
  std::unique_ptr<detail::InputWalk> walk;
  if (options.planar_flips)
    stats.planar_flips =
        detail::flip_in_planes(out.working, mesh, kPlanarFlipHeight * face_bounding_box(mesh).diagonal(), walk);
  subdivide(out.working, levels);
  if (n > out.working.mesh.num_vertices())
    throw InvalidInput("cvt: " + std::to_string(n) + " sites asked for, the mesh (split " + std::to_string(levels) +
                       " times) has only " + std::to_string(out.working.mesh.num_vertices()) + " vertices");
  stats.bisections += refine_long_edges(out.working, max_edge, out.working.mesh.num_faces() + 4 * n);
  stats.subdivisions = levels;
  stats.working_faces = out.working.mesh.num_faces();
  stats.timings.subdivide = seconds_since(t0);

  t0 = Clock::now();
  const WorkingGeometry g(out.working.mesh);
  SolverOptions solver_options;
  solver_options.threads = options.threads;
  const GeodesicSolver solver(out.working.mesh, solver_options);
  out.area = g.total_area;
  out.diagonal = g.diagonal;
  stats.timings.prepare = seconds_since(t0);

  t0 = Clock::now();
  // The feature curves' samples come first and take their share of the budget.
  FeatureSites features;
  const double spacing = std::sqrt(2.0 * g.total_area / (std::sqrt(3.0) * double(n)));
  if (options.feature_angle > 0) {
    features = feature_sites(g, options.feature_angle, spacing, kFeatureBand);
    stats.feature_sites = features.sites.size();
    stats.feature_curves = features.curves;
    stats.short_feature_curves = features.dropped_curves;
  }
  if (options.cone_angle > 0) stats.cone_sites = add_cone_sites(g, options.cone_angle, spacing, n / 50, features);
  std::vector<SurfaceSite> sites = features.sites;
  if (n > sites.size()) {
    const std::vector<SurfaceSite> free = initial_sites(mesh, out.working, g, n - sites.size(), options);
    sites.insert(sites.end(), free.begin(), free.end());
  }
  stats.initial_sites = sites.size();
  stats.timings.initial = seconds_since(t0);

  Lloyd lloyd(g, solver, options, stats);
  lloyd.loops_ = boundary_loops(g);
  if (!features.sites.empty()) lloyd.features_ = &features;
  Evaluation e = lloyd.evaluate(sites);
  if (options.fix_regions && lloyd.fix(e, sites)) e = lloyd.evaluate(sites);
  if (options.boundary_sites && !lloyd.loops_.empty()) {
    sites = lloyd.snap_to_boundary(e, sites);
    e = lloyd.evaluate(sites);
  }
  out.energy_curve.push_back(e.energy);
  auto report = [&](int it) {
    if (options.on_iteration) options.on_iteration({it, options.max_iterations, e.energy, sites.size()});
  };
  report(0);
  for (int it = 1; it <= options.max_iterations; ++it) {
    bool accepted = false;
    std::vector<SurfaceSite> candidate;
    Evaluation ce;
    // Over-relaxed step, full step, then half and quarter steps: a Lloyd step decreases the
    // exact energy, but the labels and centroids here are approximate, so near convergence a
    // step can go up.
    std::vector<double> steps{1.0, 0.5, 0.25};
    if (options.over_relaxation > 1.0) steps.insert(steps.begin(), options.over_relaxation);
    for (double t : steps) {
      candidate = lloyd.step(e, sites, t, t != 1.0);
      ce = lloyd.evaluate(candidate);
      if (ce.energy <= e.energy) {
        accepted = true;
        break;
      }
      stats.rejected_steps++;
    }
    if (!accepted) break;   // no decrease: the previous sites stay
    const double relative = (e.energy - ce.energy) / e.energy;
    sites = std::move(candidate);
    e = std::move(ce);
    bool fixed_now = false;
    if (options.fix_regions) {
      std::vector<SurfaceSite> fixed = sites;
      if (lloyd.fix(e, fixed)) {
        // Adding a site never increases the exact energy; keep the fix only if the estimate
        // agrees, so the curve stays monotone.
        Evaluation fe = lloyd.evaluate(fixed);
        if (fe.energy <= e.energy) {
          sites = std::move(fixed);
          e = std::move(fe);
          fixed_now = true;
        }
      }
    }
    stats.iterations = it;
    out.energy_curve.push_back(e.energy);
    report(it);
    if (it == options.hopeless_check_iteration) {
      const std::size_t defects = lloyd.dual_defects(e, sites, mesh);
      const double allowed = std::max(double(options.hopeless_defects), options.hopeless_fraction * double(sites.size()));
      if (double(defects) > allowed) {
        stats.stopped_hopeless = true;
        stats.hopeless_defects = defects;
        break;
      }
    }
    // After a fix the new sites still need Lloyd steps of their own.
    if (relative < options.tolerance && !fixed_now) {
      stats.converged = true;
      break;
    }
  }
  if (options.fix_regions && !stats.stopped_hopeless) {
    const std::size_t cap = std::size_t(options.max_closing_fraction * double(stats.initial_sites));
    // A round is kept only if the energy estimate does not rise (as the fixes above), so the
    // curve, which gets one entry per round and step, stays monotone.
    bool closed = lloyd.dual_has_topology(e, sites, mesh);
    for (int round = 0; round < options.closing_rounds && !closed; ++round) {
      std::vector<SurfaceSite> more = sites;
      const std::size_t added_before = stats.closing_sites;
      if (!lloyd.close_dual(e, more, cap)) break;
      Evaluation ce = lloyd.evaluate(more);
      if (!(ce.energy <= e.energy)) {
        stats.closing_sites = added_before;
        break;
      }
      sites = std::move(more);
      e = std::move(ce);
      out.energy_curve.push_back(e.energy);
      stats.closing_rounds = round + 1;
      closed = lloyd.dual_has_topology(e, sites, mesh);
    }
    // Lloyd steps after the closing even the new sites' regions out, each kept only if the
    // energy goes down and the dual keeps the topology.
    for (int it = 0; closed && stats.closing_sites > 0 && it < options.closing_steps; ++it) {
      bool kept = false;
      for (double t : {1.0, 0.5, 0.25}) {
        std::vector<SurfaceSite> candidate = lloyd.step(e, sites, t, true);
        Evaluation ce = lloyd.evaluate(candidate);
        if (!(ce.energy <= e.energy) || !lloyd.dual_has_topology(ce, candidate, mesh)) continue;
        sites = std::move(candidate);
        e = std::move(ce);
        out.energy_curve.push_back(e.energy);
        stats.closing_steps++;
        kept = true;
        break;
      }
      if (!kept) break;
    }
  }
  out.energy = e.energy;

  out.working_face_label = e.label;
  out.working_vertex_label = e.result.vertex_source;
  out.vertex_label.assign(e.result.vertex_source.begin(), e.result.vertex_source.begin() + long(mesh.num_vertices()));
  for (const SurfaceSite& s : sites) {
    out.sites.push_back(to_input(out.working, s, walk.get()));
    out.working_site_position.push_back(s.position);
    out.working_site_face.push_back(s.point.element);
  }
  return out;
}

}  // namespace gsp::cvt
