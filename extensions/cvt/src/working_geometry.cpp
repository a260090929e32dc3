#include "working_geometry.hpp"

#include <algorithm>
#include <limits>

namespace gsp::cvt::detail {

WorkingGeometry::WorkingGeometry(const TriangleMesh& m) : mesh(m), conn(build_connectivity(m)) {
  area.resize(m.num_faces());
  centroid.resize(m.num_faces());
  radius.resize(m.num_faces());
  for (Index f = 0; f < m.num_faces(); ++f) {
    const Triangle& t = m.triangles[f];
    const Vec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    const bool repeated = repeats_vertex(t);
    area[f] = repeated ? 0.0 : 0.5 * norm(cross(b - a, c - a));
    centroid[f] = (1.0 / 3.0) * (a + b + c);
    radius[f] = std::max({distance(a, centroid[f]), distance(b, centroid[f]), distance(c, centroid[f])});
    total_area += area[f];
  }
  boundary_halfedge.resize(conn.num_halfedges());
  for (Index h = 0; h < conn.num_halfedges(); ++h)
    boundary_halfedge[h] = conn.halfedge_edge[h] != kInvalidIndex && conn.radial_next[h] == h;
  diagonal = face_bounding_box(m).diagonal();
}

SurfaceSite WorkingGeometry::at(Index face, std::array<double, 3> b) const {
  // Clamp and renormalise: GSP checks that barycentrics are >= 0 and sum to 1.
  for (double& x : b) x = std::max(0.0, x);
  const double s = b[0] + b[1] + b[2];
  if (s > 0) for (double& x : b) x /= s;
  else b = {1, 0, 0};
  SurfaceSite site;
  site.point = SurfacePoint::in_face(face, b);
  site.position = site.point.position(mesh);
  return site;
}

SurfaceSite WorkingGeometry::closest_on_face(Index f, Vec3 p) const {
  const Triangle& t = mesh.triangles[f];
  return at(f, closest_point_on_triangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
}

SurfaceSite WorkingGeometry::closest_on_halfedge(Index h, Vec3 p) const {
  const Vec3 a = mesh.positions[from_vertex(mesh, h)], b = mesh.positions[to_vertex(mesh, h)];
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double s = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  std::array<double, 3> bary{0, 0, 0};
  bary[corner_of(h)] = 1 - s;
  bary[corner_of(next_halfedge(h))] = s;
  SurfaceSite site = at(face_of(h), bary);
  site.on_boundary = true;
  return site;
}

}  // namespace gsp::cvt::detail
