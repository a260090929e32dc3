#pragma once
// Quality figures of a sample set on a mesh, all measured with GSP.
#include <gsp/sampling/sampler.hpp>

#include <cstddef>
#include <cstdint>

namespace gsp::sampling {

struct QualityOptions {
  // Samples whose nearest neighbour is measured; 0 = all, else a seeded random subset. Every
  // sample still gets its propagation (bounded by 2r) for the coverage radius.
  std::size_t max_checked = 0;
  std::uint64_t seed = 1;
  ProgressFn progress;
};

struct SamplingQuality {
  std::size_t samples_checked = 0;
  // Smallest geodesic distance between a checked sample and any other sample, bounded by 2r
  // (2r when no other sample is that close); and divided by r.
  double min_distance = 0;
  double min_distance_ratio = 0;
  // Largest distance from a (referenced) vertex to its nearest sample, and divided by r:
  // the minimum over the per-sample runs bounded by 2r; vertices none of them reaches get
  // the value of one propagation from all samples at once. (Not that run alone: in a
  // multi-source GSP run a face-point source whose face is taken over by another source,
  // or shares its face with one, is lost, and vertices around it get too large values.)
  double coverage_radius = 0;
  double coverage_ratio = 0;
  // Lagae and Dutre's normalised radius: (r / 2) / packing_radius(area, N): r / 2 is the
  // radius of the non-overlapping discs around the samples. Good blue noise: 0.65 .. 0.85.
  double area = 0;
  double packing_radius = 0;
  double normalized_radius = 0;
};

// `result.radius` is r. Throws InvalidInput for an empty sample set or a sample naming a face
// the mesh does not have.
SamplingQuality measure_quality(const Sampler& sampler, const SamplingResult& result,
                                const QualityOptions& options = {});

}  // namespace gsp::sampling
