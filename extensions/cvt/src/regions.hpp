#pragma once
// Voronoi regions as sets of working-mesh faces: connected components per label, the clean-up
// of slivers of a region cut off by the face-granular boundary, and per-region sums.
#include "working_geometry.hpp"

#include <vector>

namespace gsp::cvt::detail {

struct Components {
  std::vector<Index> of_face;        // component id per face (kInvalidIndex for unlabelled faces)
  std::vector<Index> label;          // per component
  std::vector<double> area;          // per component
  std::vector<Vec3> moment;          // per component: sum of area * centroid
  std::vector<Index> main;           // per label: its main component (kInvalidIndex if none)
};

// Components of faces with the same label connected across edges. The main component of a
// label is the one holding its site's face, else its largest.
Components find_components(const WorkingGeometry& g, const std::vector<Index>& label,
                           const std::vector<Index>& site_face, std::size_t sites);

// Faces of non-main components smaller than `min_area` take the label their component
// shares most edges with. Returns the number of faces relabelled.
std::size_t absorb_small_components(const WorkingGeometry& g, std::vector<Index>& label,
                                     const Components& c, double min_area);

// Euler characteristic V - E + F of each component (1 for a disk).
std::vector<long> component_euler(const WorkingGeometry& g, const Components& c);

// Faces per label, CSR.
struct Buckets {
  std::vector<Index> begin, faces;
};
Buckets bucket_faces(const std::vector<Index>& label, std::size_t sites);

}  // namespace gsp::cvt::detail
