#pragma once
// Geodesic blue-noise sampling with GSP (paper Section 5.8, Fig. 12 c,d): sources are added
// one by one and each propagation stops after a fixed distance.
//
//   gsp::sampling::Sampler sampler(mesh);                  // prepares one GeodesicSolver
//   gsp::sampling::SamplingOptions options;
//   options.radius = 0.02 * sampler.diagonal();            // or options.count = 1000
//   auto result = sampler.sample(options);                 // result.samples: face, barycentric, ...
//   auto quality = gsp::sampling::measure_quality(sampler, result);
//
// Poisson-disk mode (dart throwing): candidates are drawn uniformly by area; a candidate
// whose geodesic distance to every earlier sample is >= r is accepted, and a GSP propagation
// from it bounded by r (plus one edge, see below) is merged into the running coverage field.
// The candidate test reads that field through the per-face virtual sources of the earlier
// runs (sigma + |p - S|, paper Fig. 7c), not by interpolating vertex values: the distance to
// a point source is convex inside a face, so linear interpolation of the corner values
// over-estimates it and would accept candidates closer than r.
//
// Farthest-point mode: start at a vertex picked by the seed, then repeatedly add the vertex
// farthest from all samples; each propagation is bounded by that current largest distance
// (a vertex farther than it from the new sample cannot get closer).
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>
#include <gsp/sampling/surface_points.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace gsp::sampling {

// Called with the fraction done in [0, 1]; may be empty.
using ProgressFn = std::function<void(double fraction)>;

enum class Mode { poisson, farthest };

struct SamplingOptions {
  Mode mode = Mode::poisson;
  // Exactly one of radius (> 0, model units) and count (> 0).
  //   poisson + radius: samples at least `radius` apart, until saturation.
  //   poisson + count:  the radius is searched (secant on log r, bisection fallback) until the
  //                     count is within count_tolerance of `count`.
  //   farthest + radius: until every vertex is closer than `radius` to a sample.
  //   farthest + count:  exactly `count` samples (fewer if the mesh has fewer vertices).
  double radius = 0;
  std::size_t count = 0;
  std::uint64_t seed = 1;
  // Poisson: stop after this many consecutive rejected candidates...
  std::size_t max_rejections = 500;
  // ...then add a sample at every vertex still at distance >= r (in a seeded random order),
  // so that every vertex ends closer than r to a sample (a maximal sampling up to gaps
  // smaller than an edge). Off: pure dart throwing.
  bool fill_vertices = true;
  double count_tolerance = 0.01;    // relative, for poisson + count
  // poisson + count: exactly `count` samples. The search then looks for a run with at least
  // `count` samples (within count_tolerance above it) and drops the last-added surplus, so
  // samples stay at least `radius` apart; the coverage is recomputed from the kept samples.
  // When no run reaches `count` (more samples than the mesh holds at any radius the search
  // tried) the largest run is returned and count_met is false.
  bool exact_count = false;
  int max_search_iterations = 30;   // sampling runs for poisson + count
  ProgressFn progress;
};

struct SamplingStats {
  std::uint64_t candidates = 0;     // darts thrown (last run in count mode)
  std::uint64_t rejected = 0;
  std::uint64_t fill_samples = 0;   // samples added by the vertex fill pass
  std::uint64_t propagations = 0;   // GSP runs, all search iterations included
  std::uint64_t update_steps = 0;   // summed over all runs
  std::uint64_t faces_reached = 0;  // summed over all runs
  int search_iterations = 0;        // poisson + count: sampling runs made
  bool count_met = true;            // poisson + count: within tolerance
};

struct SamplingResult {
  std::vector<Sample> samples;
  // Poisson: the disc radius r (minimum distance between samples). Farthest: the distance of
  // the last sample from the earlier ones when it was added (no two samples are closer).
  double radius = 0;
  // Per vertex, the distance to the nearest sample as far as the bounded runs reached
  // (+inf beyond); unreferenced vertices stay +inf.
  std::vector<double> coverage;
  SamplingStats stats;
};

// Prepares a mesh once (one GeodesicSolver, face areas) and samples it any number of times.
// Keeps a reference to `mesh`: it must outlive the sampler.
class Sampler {
 public:
  explicit Sampler(const TriangleMesh& mesh, const SolverOptions& options = {});

  // Throws InvalidInput for options that contradict each other (both or neither of radius
  // and count, a non-finite radius) or a mesh without area.
  SamplingResult sample(const SamplingOptions& options) const;

  const TriangleMesh& mesh() const { return mesh_; }
  const GeodesicSolver& solver() const { return solver_; }
  double area() const { return points_.total_area(); }
  double diagonal() const { return diagonal_; }        // of the axis-aligned bounding box
  double longest_edge() const { return longest_edge_; }
  // Vertices used by at least one face (the ones the coverage figures are about).
  const std::vector<bool>& referenced() const { return referenced_; }

 private:
  SamplingResult poisson(double radius, const SamplingOptions& options) const;
  SamplingResult poisson_count(const SamplingOptions& options) const;
  SamplingResult farthest(const SamplingOptions& options) const;

  const TriangleMesh& mesh_;
  GeodesicSolver solver_;
  // Faces that are part of the surface as the solver sees it (GeodesicSolver::face_takes_part:
  // not a face naming a vertex twice, nor a doubled face's copy), with a positive area. Darts
  // land on these only: the propagations never reach a copy, so a sample there was never seen
  // by the next candidate's test and darts on it were accepted without end.
  std::vector<bool> taking_part_;
  AreaSampler points_;
  double diagonal_ = 0, longest_edge_ = 0;
  std::vector<bool> referenced_;
  std::vector<Index> vertex_face_;   // one face using each vertex (kInvalidIndex if none)
};

// The radius of the densest packing of `count` equal discs on area `area`
// (hexagonal): r_max = sqrt(A / (2 sqrt(3) N)) (Lagae and Dutre 2008). The discs' centres are
// then 2 r_max apart.
double packing_radius(double area, std::size_t count);

}  // namespace gsp::sampling
