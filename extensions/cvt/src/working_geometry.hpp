#pragma once
// What the Lloyd iterations read of the working mesh: connectivity, face areas and
// centroids, boundary halfedges; and points on it (sites).
#include <gsp/closest_point.hpp>
#include <gsp/connectivity.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/mesh.hpp>

#include <array>
#include <vector>

namespace gsp::cvt::detail {

using SurfaceSite = Site;   // a site on the working mesh

struct WorkingGeometry {
  explicit WorkingGeometry(const TriangleMesh& m);

  const TriangleMesh& mesh;
  Connectivity conn;
  std::vector<double> area;
  std::vector<Vec3> centroid;
  std::vector<double> radius;   // the centroid's largest distance to a corner
  std::vector<bool> boundary_halfedge;   // ring of one
  double total_area = 0;
  double diagonal = 0;

  SurfaceSite at(Index face, std::array<double, 3> bary) const;
  // Closest point to p on face f / on the segment of halfedge h.
  SurfaceSite closest_on_face(Index f, Vec3 p) const;
  SurfaceSite closest_on_halfedge(Index h, Vec3 p) const;
};

}  // namespace gsp::cvt::detail
