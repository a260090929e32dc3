#pragma once
// Geodesic centroidal Voronoi tessellation (CVT) by Lloyd iterations with GSP.
//
//   gsp::cvt::CvtOptions options;
//   options.sites = 2000;                          // or options.edge_length = ...
//   gsp::cvt::CvtResult cvt = gsp::cvt::compute_cvt(mesh, options);
//   cvt.sites[i].position, cvt.energy_curve, cvt.vertex_label (per input vertex)
//   gsp::TriangleMesh remeshed = gsp::cvt::restricted_delaunay(cvt);   // remesh.hpp
//
// Every Lloyd iteration is one multi-source GSP propagation from all sites (points inside
// faces); its per-face labels are the geodesic Voronoi regions. The work happens on a
// "working mesh": the input split 1-to-4 (edge midpoints, so the surface is unchanged) until
// it has at least `min_faces_per_site` faces per site, because regions a few faces wide have
// centroids and boundaries only as fine as the faces. See docs/cvt.md.
#include <gsp/geodesics.hpp>
#include <gsp/mesh.hpp>
#include <gsp/surface_point.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace gsp::cvt {

// poisson: geodesic Poisson-disk samples (gsp::sampling, count search on the input mesh);
// farthest: farthest-point samples; random: area-uniform white noise (no propagation at all,
// Lloyd then needs more iterations).
enum class InitialSites { poisson, farthest, random };

// Called after every evaluated iteration (0 = the initial sites).
struct IterationInfo {
  int iteration = 0;
  int max_iterations = 0;
  double energy = 0;
  std::size_t sites = 0;
};
using IterationFn = std::function<void(const IterationInfo&)>;

// How far (relative to the bounding box's diagonal) the four corners of a flipped working-mesh
// edge may lie off one plane: the surface moves by at most that (float STL coordinates of one
// plane are off it by about 1e-7 of the diagonal).
inline constexpr double kPlanarFlipHeight = 1e-6;

struct CvtOptions {
  // Exactly one of sites (> 0) and edge_length (> 0, model units; converted to a site count
  // by N = 2 A / (sqrt(3) L^2), the vertex count of an equilateral triangulation of area A).
  std::size_t sites = 0;
  double edge_length = 0;
  int max_iterations = 50;
  // Stop when (E_prev - E) / E_prev < tolerance.
  double tolerance = 1e-4;
  // Each Lloyd step first tries site + w (centroid - site) with this w (over-relaxation; 1:
  // off), then 1, 1/2, 1/4, keeping the first that lowers the energy. 1.6 took 15 instead
  // of 18 iterations (fertility) and 25 instead of 30 (armadillo) at 5,000 sites, to a lower
  // energy, with no step rejected (docs/cvt.md).
  double over_relaxation = 1.6;
  InitialSites initial = InitialSites::poisson;
  std::uint64_t seed = 1;
  // Working-mesh resolution (see above); 0: no split. The fewest levels that reach it leave
  // 12-48 faces per site, 24 on a geometric average. 24 (24-96 per site) measured the same
  // quality on the corpus at 1.6-1.7x the time (docs/cvt.md, "Working-mesh resolution").
  std::size_t min_faces_per_site = 12;
  // The faces-per-site rule above stops the splitting first (at most 4 * min_faces_per_site
  // faces per site); the cap only matters for inputs of very few faces (CAD parts, a lone
  // triangle), which need many levels before a region is more than a few faces wide.
  int max_subdivisions = 10;
  // Detect regions that are not a single disk (several components, or one that wraps around a
  // handle) and add a site there; also keep at least 3 regions along every boundary loop and
  // one run of regions per loop (a region touching a loop twice gets a second site).
  bool fix_regions = true;
  double max_added_fraction = 0.05;   // the fixes add at most this fraction of the sites
  // After the iterations, while the dual is not a manifold with the input's topology, up to
  // `closing_rounds` rounds add a site wherever it goes wrong (the same three regions meeting
  // twice, two regions with a border of more than two ends), with no Lloyd step after them; at
  // most max_closing_fraction of the sites. A round is kept only if the energy estimate does
  // not rise.
  int closing_rounds = 16;
  double max_closing_fraction = 0.25;
  // Then up to this many Lloyd steps, each kept only if the energy goes down and the dual
  // keeps the topology.
  int closing_steps = 3;
  // For a remesh (remesh_surface sets it: SurfaceRemeshOptions::hopeless_check_iteration):
  // after this many Lloyd steps the dual is checked once, and wrong at more than
  // max(hopeless_defects, hopeless_fraction * sites) places (non-manifold edges and vertices,
  // as same_topology_per_component counts them) the loop and the closing rounds stop there
  // (CvtStats::stopped_hopeless) and the result goes back as it is. 0 (the default here): the
  // CVT is computed to the end whatever its dual.
  int hopeless_check_iteration = 0;
  std::size_t hopeless_defects = 50;
  double hopeless_fraction = 0.02;
  // Sites whose region touches the mesh boundary are kept on the boundary: they move to the
  // point of their region's boundary arc closest to the area centroid (the constrained
  // minimiser of the region's energy in the Euclidean approximation). Needed for the dual
  // mesh to have the input's boundary.
  bool boundary_sites = true;
  // The memory the CVT may plan its working mesh for, in bytes: 0 = what the machine has
  // available (MemAvailable, or the process's address-space limit if lower). A site count whose
  // working mesh would need more is refused (InvalidInput) before it is built, instead of
  // growing until the kernel kills the process.
  std::size_t max_memory = 0;
  // Sharp features kept (0: off): edges whose faces' normals differ by more than this many
  // degrees form crease curves; each curve at least one site spacing long gets fixed sites at
  // even arc-length steps of about the spacing, from corner to corner (the 1D CVT of the
  // curve), and the faces around it belong to those sites, so the remesh has each curve as a
  // chain of edges and every corner as a vertex. The fixed sites count towards `sites`.
  double feature_angle = 0;
  // Spike tips kept (0: off, the default; 240 is a good value): an interior vertex of the input
  // whose angles sum to less than this many degrees but at least half of it (a horn's tip, a
  // tetrahedron's corner; a flat vertex has 360) gets a fixed site, so the remesh has a vertex
  // there instead of cutting the tip off. The sharpest first, none within a site spacing of
  // another fixed site, at most one site in 50. They count towards `sites`. Off by default:
  // on the corpus it lowers the Hausdorff distance of spiky scans but moves every site, and
  // the 20-degree floor was lost on one more file in each category (docs/cvt.md, "Spike tips").
  double cone_angle = 0;
  // Threads of the geodesic solver (its preparation and each propagation): 0 = automatic (two
  // or more on working meshes of at least kParallelMinFaces faces), 1 = one. On several
  // threads a propagation's ties fall in the order the threads reach them (GSP's order
  // effects), a face near a border between two regions can change sides, and the remesh then
  // differs from run to run in a few places; on one thread it is the same every time, at
  // 10-20% more time for working meshes that large (docs/cvt.md). remesh_surface remeshes
  // the components side by side on that many threads instead (0: all cores), each of them on
  // one thread, unless one component has more than 3/4 of the sites.
  unsigned threads = 0;
  // Delaunay flips of the working mesh's edges whose four corners lie in one plane (within
  // kPlanarFlipHeight of the diagonal): CAD exports' flat faces are fans of slivers, on which
  // GSP's regions went wrong (docs/cvt.md, "Slivers in planes").
  bool planar_flips = true;
  IterationFn on_iteration;
};

// A site: a point in a face (face kInvalidIndex until placed), its position, and whether it
// was placed on the boundary. CvtResult::sites are on the input mesh; the iterations keep
// theirs on the working mesh.
struct Site {
  SurfacePoint point = SurfacePoint::in_face(kInvalidIndex, {1, 0, 0});
  Vec3 position;
  bool on_boundary = false;
  bool fixed = false;   // a sample of a sharp feature curve or a spike tip (CvtOptions::feature_angle,
                        // cone_angle): never moves
};

struct CvtTimings {   // seconds
  double subdivide = 0, prepare = 0, initial = 0, propagate = 0, centroids = 0, fix = 0;
  // Phase by phase (remesh_surface sums the attempts and the components).
  CvtTimings& operator+=(const CvtTimings& t) {
    subdivide += t.subdivide, prepare += t.prepare, initial += t.initial;
    propagate += t.propagate, centroids += t.centroids, fix += t.fix;
    return *this;
  }
};

struct CvtStats {
  int iterations = 0;              // Lloyd steps accepted
  int rejected_steps = 0;          // steps whose energy rose and were shortened
  std::size_t initial_sites = 0;
  std::size_t sites_added = 0;     // by the region fixes
  std::size_t sites_relocated = 0; // sites that lost their whole region and were moved
  std::size_t split_regions = 0;   // regions found with several components (all iterations)
  std::size_t nondisk_regions = 0; // single-component regions that are not disks
  std::size_t junction_fixes = 0;  // sites added where the dual would not be manifold
  std::size_t closing_sites = 0;   // of those, added after the iterations (CvtOptions::closing_rounds)
  int closing_rounds = 0;
  int closing_steps = 0;           // Lloyd steps kept after the closing
  std::size_t feature_sites = 0;   // fixed on the crease curves (CvtOptions::feature_angle)
  std::size_t feature_curves = 0;  // curves kept (of which too short to keep:)
  std::size_t short_feature_curves = 0;
  std::size_t cone_sites = 0;      // fixed at spike tips (CvtOptions::cone_angle)
  std::size_t working_faces = 0;
  int subdivisions = 0;
  std::size_t bisections = 0;      // long edges split after the uniform subdivision
  std::size_t planar_flips = 0;    // working-mesh edges flipped inside planes (CvtOptions::planar_flips)
  bool converged = false;          // tolerance met (else the iteration cap or no decrease)
  bool stopped_hopeless = false;   // stopped at CvtOptions::hopeless_check_iteration
  std::size_t hopeless_defects = 0;   // the places the dual was wrong at then
  std::uint64_t update_steps = 0;  // GSP update steps over all propagations
  std::size_t propagations = 0;
  CvtTimings timings;
};

// The working mesh: the input's long edges bisected, then split `levels` times 1-to-4, then
// long edges bisected again (compute_cvt; subdivide alone does the split). Its
// first V vertices are the input's vertices; face f of it lies in input face parent[f], its
// corner k at the parent's barycentric coordinates corner_bary[f][k].
struct WorkingMesh {
  TriangleMesh mesh;
  std::vector<Index> parent;
  std::vector<std::array<std::array<double, 3>, 3>> corner_bary;
  int levels = 0;
};
WorkingMesh subdivide(const TriangleMesh& mesh, int levels);
// The same split of a working mesh (after refine_long_edges, say), `levels` more times.
void subdivide(WorkingMesh& w, int levels);

// Longest-edge bisection (conforming: an edge is split in all its faces) until no edge is
// longer than max_edge, or the mesh has max_faces faces, or after 12 passes; the surface does
// not move. For inputs
// whose faces differ much in size (a flat base of a few large triangles under a fine scan),
// where uniform splitting leaves faces larger than a Voronoi region and two sites share a face
// (GSP then keeps only one of them). Returns the number of edges split.
std::size_t refine_long_edges(WorkingMesh& w, double max_edge, std::size_t max_faces);

struct CvtResult {
  std::vector<Site> sites;
  // Energy of the accepted sites, per iteration (0 = initial), then per closing round and step.
  std::vector<double> energy_curve;
  double energy = 0;                    // last entry of energy_curve
  // Labels of the final sites' Voronoi regions: per input vertex, and on the working mesh
  // per vertex and per face (index into sites; kInvalidIndex where unreached).
  std::vector<Index> vertex_label;
  WorkingMesh working;
  std::vector<Index> working_vertex_label;
  std::vector<Index> working_face_label;
  std::vector<Vec3> working_site_position;   // = sites[i].position
  std::vector<Index> working_site_face;      // the site's face on the working mesh
  double area = 0, diagonal = 0;
  CvtStats stats;
};

// Throws InvalidInput for contradictory options (both or neither of sites and edge_length),
// a mesh without area, or more sites than the working mesh has vertices.
CvtResult compute_cvt(const TriangleMesh& mesh, const CvtOptions& options);

// The CVT energy of a labelling: sum over faces of the integral of the squared geodesic
// distance to the face's source, by the edge-midpoint rule (exact for quadratics) on the
// distance sigma + |p - S| of the face's virtual source. Needs want_face_sources.
double cvt_energy(const TriangleMesh& mesh, const GeodesicResult& result);

}  // namespace gsp::cvt
