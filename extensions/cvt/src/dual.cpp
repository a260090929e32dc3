// The restricted Delaunay dual of face-labelled Voronoi regions (see remesh.hpp).
#include "junctions.hpp"
#include "post_pass.hpp"

#include <gsp/cvt/remesh.hpp>
#include <gsp/errors.hpp>

#include <algorithm>

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
  if (options.accept_dual && !options.accept_dual(r.mesh)) return r;
  // The feature curves' samples and the edges between them stay as the dual made them.
  std::vector<bool> locked(r.vertex_site.size(), false);
  for (std::size_t v = 0; v < locked.size(); ++v) locked[v] = cvt.sites[r.vertex_site[v]].fixed;
  const std::vector<bool>* lock = std::count(locked.begin(), locked.end(), true) ? &locked : nullptr;
  // The working mesh is the input's surface; projecting onto the input itself (rebuilt from
  // the working faces' parents, far fewer faces) is faster but ends in lower minimum angles
  // (docs/cvt.md, the post-pass's cost).
  detail::improve_remesh(r.mesh, r.vertex_site, cvt.working.mesh, cvt.diagonal, cvt.sites.size(), options, lock, r.stats);
  return r;
}

}  // namespace gsp::cvt
