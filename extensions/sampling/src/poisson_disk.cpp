// Sampler set-up, option checks, and Poisson-disk sampling at a given radius.
#include "coverage_field.hpp"

#include <gsp/available_memory.hpp>
#include <gsp/errors.hpp>
#include <gsp/sampling/sampler.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace gsp::sampling {

namespace {

std::vector<bool> faces_taking_part(const TriangleMesh& mesh, const GeodesicSolver& solver) {
  std::vector<bool> part(mesh.num_faces());
  for (std::size_t f = 0; f < part.size(); ++f) part[f] = solver.face_takes_part(Index(f)) && triangle_area(mesh, Index(f)) > 0;
  return part;
}

}  // namespace

Sampler::Sampler(const TriangleMesh& mesh, const SolverOptions& options)
    : mesh_(mesh), solver_(mesh, options), taking_part_(faces_taking_part(mesh, solver_)), points_(mesh, taking_part_) {
  referenced_.assign(mesh.num_vertices(), false);
  vertex_face_.assign(mesh.num_vertices(), kInvalidIndex);
  for (std::size_t f = 0; f < mesh.num_faces(); ++f) {
    const Triangle& t = mesh.triangles[f];
    if (!taking_part_[f]) continue;   // no area (a sample there would have no normal), or a copy
    for (int i = 0; i < 3; ++i) {
      referenced_[t[i]] = true;
      if (vertex_face_[t[i]] == kInvalidIndex) vertex_face_[t[i]] = Index(f);
      longest_edge_ = std::max(longest_edge_, distance(mesh.positions[t[i]], mesh.positions[t[(i + 1) % 3]]));
    }
  }
  diagonal_ = bounding_box(mesh).diagonal();
}

double packing_radius(double area, std::size_t count) {
  return count ? std::sqrt(area / (2 * std::sqrt(3.0) * double(count))) : 0.0;
}

namespace {

// Peak bytes per sample of a sampling run (the samples, their coverage records and the bounded
// fields' state): measured 0.8-1.2 KB on spot at 100k-1M samples (gsp-sample, peak RSS).
constexpr double kBytesPerSample = 1200;
// A maximal Poisson-disk sampling holds about this share of the densest packing's count (the
// estimate of a radius's count, on the low side: no feasible run is refused).
constexpr double kPoissonShareOfPacking = 0.5;

}  // namespace

SamplingResult Sampler::sample(const SamplingOptions& options) const {
  const bool by_radius = options.radius != 0, by_count = options.count != 0;
  if (by_radius == by_count) throw InvalidInput("sampling: give exactly one of a radius and a count");
  if (by_radius && !(std::isfinite(options.radius) && options.radius > 0))
    throw InvalidInput("sampling: the radius must be finite and > 0");
  if (!(options.count_tolerance >= 0)) throw InvalidInput("sampling: the count tolerance must be >= 0");
  // Far more samples than the machine can hold are refused up front: gsp-sample --count
  // 100000000 on an 11k-vertex mesh grew past 6 GB in two minutes.
  const double samples =
      by_count ? double(options.count) : kPoissonShareOfPacking * area() / (2 * std::sqrt(3.0) * options.radius * options.radius);
  char what[80];
  std::snprintf(what, sizeof what, "sampling: about %.3g samples", samples);
  require_memory(what, samples * kBytesPerSample, "samples (or a larger radius)");
  if (options.mode == Mode::farthest) return farthest(options);
  if (options.max_rejections == 0) throw InvalidInput("sampling: max_rejections must be > 0");
  return by_radius ? poisson(options.radius, options) : poisson_count(options);
}

namespace {

constexpr std::size_t kBatch = 1024;   // candidates sorted together

void count_run(SamplingStats& stats, const LocalField& run) {
  ++stats.propagations;
  stats.update_steps += run.stats.update_steps;
  stats.faces_reached += run.stats.faces_reached;
}

}  // namespace

SamplingResult Sampler::poisson(double radius, const SamplingOptions& options) const {
  SamplingResult result;
  result.radius = radius;
  detail::CoverageField field(mesh_, referenced_, radius);
  // Bounded at r: the propagation still reaches every face that can hold a point within r
  // (GeodesicOptions::max_distance), so the stored virtual sources cover all that matters.
  GeodesicOptions go;
  go.max_distance = radius;
  go.want_face_sources = true;

  Random random(options.seed);
  LocalWorkspace workspace = solver_.make_workspace();
  // Runs the candidate's propagation; keeps it unless it reaches an earlier sample closer
  // than r (the other direction of the test, see CoverageField::clear_of_samples).
  auto accept = [&](const Sample& s) {
    const LocalField run = solver_.compute_local({Source::at(s.point)}, go, workspace);
    count_run(result.stats, run);
    if (!field.clear_of_samples(run)) return false;
    field.merge(run);
    field.add_sample(s.point.element, s.point.barycentric);
    result.samples.push_back(s);
    if (options.progress && field.referenced_count())
      options.progress(1.0 - double(field.uncovered()) / double(field.referenced_count()));
    return true;
  };

  // Candidates come in batches, each processed in the solver's cache layout order: runs then
  // sweep the memory forward instead of jumping at random (the dart throwing stays the same:
  // each candidate is accepted iff no earlier sample is within r). Darts stop after
  // max_rejections in a row, or once every vertex is within r of a sample.
  std::vector<Sample> batch;
  std::size_t rejected_in_a_row = 0;
  auto throw_darts = [&](const AreaSampler& from, bool until_vertices_covered) {
    auto open = [&] { return !until_vertices_covered || field.uncovered() > 0; };
    while (rejected_in_a_row < options.max_rejections && open()) {
      batch.clear();
      for (std::size_t i = 0; i < kBatch; ++i) batch.push_back(from.draw(mesh_, random));
      std::stable_sort(batch.begin(), batch.end(), [&](const Sample& a, const Sample& b) {
        return solver_.face_memory_rank(a.point.element) < solver_.face_memory_rank(b.point.element);
      });
      for (const Sample& s : batch) {
        if (rejected_in_a_row >= options.max_rejections || !open()) break;
        ++result.stats.candidates;
        if (field.distance_at(s.point.element, s.position) < radius || !accept(s)) {
          ++result.stats.rejected;
          ++rejected_in_a_row;
          continue;
        }
        rejected_in_a_row = 0;
      }
    }
  };
  throw_darts(points_, true);
  // Covered vertices stand for a covered surface only where faces are smaller than r: a
  // face with a longer edge (a CAD part's flat faces, a single triangle) has room for more
  // samples once its corners are covered. Darts go on over those faces alone, until
  // max_rejections in a row.
  if (field.uncovered() == 0 && rejected_in_a_row < options.max_rejections) {
    std::vector<bool> large(mesh_.num_faces(), false);
    bool any = false;
    for (std::size_t f = 0; f < mesh_.num_faces(); ++f) {
      const Triangle& t = mesh_.triangles[f];
      double longest = 0;
      for (int i = 0; i < 3; ++i) longest = std::max(longest, distance(mesh_.positions[t[i]], mesh_.positions[t[(i + 1) % 3]]));
      large[f] = longest > radius && taking_part_[f];
      any = any || large[f];
    }
    if (any) {
      const AreaSampler large_faces(mesh_, large);
      throw_darts(large_faces, false);
    }
  }

  if (options.fill_vertices && field.uncovered() > 0) {
    std::vector<Index> order(mesh_.num_vertices());
    std::iota(order.begin(), order.end(), Index(0));
    for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[random.below(i)]);
    for (Index v : order) {
      if (!referenced_[v] || field.vertex()[v] < radius) continue;
      const Index f = vertex_face_[v];
      const Triangle& t = mesh_.triangles[f];
      std::array<double, 3> b{0, 0, 0};
      b[t[0] == v ? 0 : (t[1] == v ? 1 : 2)] = 1;
      if (accept(make_sample(mesh_, f, b))) ++result.stats.fill_samples;
    }
  }
  result.coverage = field.vertex();
  return result;
}

}  // namespace gsp::sampling
