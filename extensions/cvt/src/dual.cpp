// The restricted Delaunay dual of face-labelled Voronoi regions (see remesh.hpp).
#include "flips.hpp"
#include "junctions.hpp"

#include <gsp/cvt/remesh.hpp>
#include <gsp/errors.hpp>

namespace gsp::cvt {

RemeshResult restricted_delaunay(const CvtResult& cvt, const RemeshOptions& options) {
  const TriangleMesh& m = cvt.working.mesh;
  const std::vector<Index>& label = cvt.working_face_label;
  if (label.size() != m.num_faces()) throw InvalidInput("restricted_delaunay: labels do not match the working mesh");
  detail::DualTriangles d = detail::dual_triangles(m, build_connectivity(m), label, cvt.working_site_position);
  RemeshResult r;
  r.stats = d.stats;
  std::vector<Index> remap(cvt.sites.size(), kInvalidIndex);
  for (Triangle& t : d.triangles)
    for (Index& x : t) {
      if (remap[x] == kInvalidIndex) {
        remap[x] = Index(r.vertex_site.size());
        r.vertex_site.push_back(x);
        r.mesh.positions.push_back(cvt.sites[x].position);
      }
      x = remap[x];
    }
  r.mesh.triangles = std::move(d.triangles);
  r.stats.unused_sites = cvt.sites.size() - r.vertex_site.size();
  if (options.flip_edges) r.stats.flips = detail::improve_by_flips(r.mesh, options.flip_max_normal_angle);
  return r;
}

}  // namespace gsp::cvt
