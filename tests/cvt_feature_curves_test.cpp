// CvtOptions::feature_angle: sharp feature curves kept by the remesh as chains of edges, their
// corners as vertices; on shapes whose features are known exactly (a box: open curves between
// corners; a capped cylinder: closed curves without corners; a folded plate: a crease that ends
// on the boundary).
#include "helpers/mesh_builders.hpp"

#include <gsp/cvt/components.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/surface.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <utility>

namespace {

using namespace gsp;

constexpr double kPi = 3.14159265358979323846;

// The box [0,2]x[0,1]x[0,height] as 12 triangles, outward.
TriangleMesh box(double height = 1.0) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({(i & 1) * 2.0, double((i >> 1) & 1), ((i >> 2) & 1) * height});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({Index(q[0]), Index(q[1]), Index(q[2])});
    m.triangles.push_back({Index(q[0]), Index(q[2]), Index(q[3])});
  }
  return m;
}

// The tube of mesh_builders (radius 1, height `rings`) closed by a fan at each end.
TriangleMesh capped_cylinder(int segments, int rings) {
  TriangleMesh m = test::cylinder(segments, rings);
  const Index s = Index(segments), top = Index(rings) * s;
  const Index bottom_centre = Index(m.positions.size());
  m.positions.push_back({0, 0, 0});
  const Index top_centre = Index(m.positions.size());
  m.positions.push_back({0, 0, double(rings)});
  for (Index i = 0; i < s; ++i) {
    m.triangles.push_back({bottom_centre, (i + 1) % s, i});
    m.triangles.push_back({top_centre, top + i, top + (i + 1) % s});
  }
  return m;
}

// Two 2x1 plates meeting along the y axis at a right angle (a crease whose ends lie on the
// boundary), 4 x 2 quads each.
TriangleMesh folded_plate() {
  TriangleMesh m;
  auto at = [&](int i, int j) { return Index(i * 3 + j); };   // i = 0..8 along x then up z, j = 0..2 along y
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 2; ++j) {
      const double x = i <= 4 ? -2.0 + 0.5 * i : 0.0, z = i <= 4 ? 0.0 : 0.5 * (i - 4);
      m.positions.push_back({x, 0.5 * j, z});
    }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 2; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

cvt::SurfaceRemeshResult remesh(const TriangleMesh& m, std::size_t sites, double feature_angle) {
  cvt::SurfaceRemeshOptions o;
  o.cvt.sites = sites;
  o.cvt.feature_angle = feature_angle;
  return cvt::remesh_surface(m, o);
}

// True when some vertex of m lies at p (to 1e-9).
bool has_vertex_at(const TriangleMesh& m, Vec3 p) {
  return std::any_of(m.positions.begin(), m.positions.end(), [&](Vec3 q) { return distance(p, q) < 1e-9; });
}

std::set<std::pair<Index, Index>> edges_of(const TriangleMesh& m) {
  std::set<std::pair<Index, Index>> e;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) e.insert(std::minmax(t[k], t[(k + 1) % 3]));
  return e;
}

// The output vertices on a curve (`param` gives the position along it, or NaN off it), sorted
// along it: every consecutive pair must be an edge of the mesh. Returns how many there are.
std::size_t check_chain(const TriangleMesh& m, const std::function<double(Vec3)>& param, bool closed,
                        const char* what) {
  std::vector<std::pair<double, Index>> on;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const double t = param(m.positions[v]);
    if (std::isfinite(t)) on.push_back({t, v});
  }
  std::sort(on.begin(), on.end());
  const auto edges = edges_of(m);
  for (std::size_t i = 0; i + 1 < on.size() + (closed ? 1 : 0); ++i) {
    const Index a = on[i].second, b = on[(i + 1) % on.size()].second;
    EXPECT_TRUE(edges.count(std::minmax(a, b))) << what << ": no edge between the vertices at " << on[i].first
                                                 << " and " << on[(i + 1) % on.size()].first;
  }
  return on.size();
}

TEST(CvtFeatureCurves, BoxKeepsEveryCornerAndEdge) {
  const TriangleMesh in = box();
  const cvt::SurfaceRemeshResult r = remesh(in, 400, 40.0);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_TRUE(cvt::same_topology_per_component(in, r.mesh));
  EXPECT_EQ(r.cvt_stats.feature_curves, 12u);
  // 2x1x1 at 400 sites: spacing ~0.2, so about 10 samples on a long edge, 5 on a short one.
  EXPECT_GE(r.cvt_stats.feature_sites, 8u + 4 * 8 + 8 * 3);
  const double eps = 1e-9;
  for (const Vec3& c : in.positions)
    EXPECT_TRUE(has_vertex_at(r.mesh, c)) << "corner " << c.x << " " << c.y << " " << c.z << " is not a vertex";
  // Each of the 12 box edges: the output vertices on it, from corner to corner, are a chain.
  for (int axis = 0; axis < 3; ++axis)
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        const double size[3] = {2, 1, 1};
        auto param = [&](Vec3 p) {
          const double c[3] = {p.x, p.y, p.z};
          if (std::abs(c[u] - a * size[u]) > eps || std::abs(c[w] - b * size[w]) > eps) return std::nan("");
          return c[axis];
        };
        EXPECT_GE(check_chain(r.mesh, param, false, "box edge"), 3u);
      }
  // The faces are flat and the edges kept: the remesh is the box.
  const cvt::HausdorffDistance hd = cvt::hausdorff_distance(in, r.mesh);
  EXPECT_LT(hd.two_sided, 1e-6 * hd.diagonal);
  EXPECT_GE(cvt::measure_mesh_quality(r.mesh).min_angle, 30.0);
}

TEST(CvtFeatureCurves, ThinPlateEdgeFacesAreSharedByTheirTwoCurves) {
  // A 2 x 1 x 0.05 plate at 400 sites (spacing ~0.1): its four edge faces are strips narrower
  // than the band, so they hold no free site and their two curves' samples share them out.
  const TriangleMesh in = box(0.05);
  const cvt::SurfaceRemeshResult r = remesh(in, 400, 40.0);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_FALSE(r.components[0].features_dropped);
  EXPECT_TRUE(cvt::same_topology_per_component(in, r.mesh));
  for (const Vec3& c : in.positions) EXPECT_TRUE(has_vertex_at(r.mesh, c));
  const cvt::HausdorffDistance hd = cvt::hausdorff_distance(in, r.mesh);
  EXPECT_LT(hd.two_sided, 1e-6 * hd.diagonal);
  // Triangles across a strip of width w between samples about h apart: angles near
  // atan(w / (h / 2)); 21.8 degrees measured.
  EXPECT_GE(cvt::measure_mesh_quality(r.mesh).min_angle, 15.0);
}

TEST(CvtFeatureCurves, WithoutFeaturesTheBoxIsChamfered) {
  // The contrast that makes the test above mean something: the same run without features
  // cuts the edges (docs/cvt.md: 2% of the diagonal on a finer box).
  const TriangleMesh in = box();
  const cvt::SurfaceRemeshResult r = remesh(in, 400, 0.0);
  EXPECT_EQ(r.cvt_stats.feature_sites, 0u);
  const cvt::HausdorffDistance hd = cvt::hausdorff_distance(in, r.mesh);
  EXPECT_GT(hd.two_sided, 1e-3 * hd.diagonal);
}

TEST(CvtFeatureCurves, CylinderRimsAreClosedChains) {
  const TriangleMesh in = capped_cylinder(48, 3);
  const cvt::SurfaceRemeshResult r = remesh(in, 600, 40.0);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_TRUE(cvt::same_topology_per_component(in, r.mesh));
  EXPECT_EQ(r.cvt_stats.feature_curves, 2u);
  for (double z : {0.0, 3.0}) {
    // On the rim the vertices are those of the input polygon's edges (radius <= 1).
    auto param = [&](Vec3 p) {
      const double rho = std::hypot(p.x, p.y);
      if (std::abs(p.z - z) > 1e-9 || rho < std::cos(kPi / 48) - 1e-9) return std::nan("");
      return std::atan2(p.y, p.x);
    };
    EXPECT_GE(check_chain(r.mesh, param, true, "rim"), 12u);
  }
  EXPECT_GE(cvt::measure_mesh_quality(r.mesh).min_angle, 25.0);
}

TEST(CvtFeatureCurves, CreaseEndingOnTheBoundary) {
  const TriangleMesh in = folded_plate();
  const cvt::SurfaceRemeshResult r = remesh(in, 150, 40.0);
  ASSERT_EQ(r.remeshed(), 1u);
  EXPECT_TRUE(cvt::same_topology_per_component(in, r.mesh));
  EXPECT_EQ(r.cvt_stats.feature_curves, 1u);
  auto param = [](Vec3 p) { return std::abs(p.x) < 1e-9 && std::abs(p.z) < 1e-9 ? p.y : std::nan(""); };
  EXPECT_GE(check_chain(r.mesh, param, false, "crease"), 4u);
  // Both ends of the crease (on the boundary) are vertices.
  EXPECT_TRUE(has_vertex_at(r.mesh, Vec3{0, 0, 0}));
  EXPECT_TRUE(has_vertex_at(r.mesh, Vec3{0, 1, 0}));
  const cvt::HausdorffDistance hd = cvt::hausdorff_distance(in, r.mesh);
  EXPECT_LT(hd.two_sided, 1e-6 * hd.diagonal);
}

TEST(CvtFeatureCurves, FixedSitesStayOnTheCurves) {
  cvt::CvtOptions o;
  o.sites = 300;
  o.feature_angle = 40.0;
  const cvt::CvtResult r = cvt::compute_cvt(box(), o);
  std::size_t fixed = 0;
  for (const cvt::Site& s : r.sites) {
    if (!s.fixed) continue;
    ++fixed;
    const Vec3 p = s.position;
    // On a box edge: at least two coordinates at their bounds.
    const int at_bound = (p.x == 0 || p.x == 2) + (p.y == 0 || p.y == 1) + (p.z == 0 || p.z == 1);
    EXPECT_GE(at_bound, 2) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_EQ(fixed, r.stats.feature_sites);
  EXPECT_GT(fixed, 0u);
  EXPECT_EQ(r.sites.size() - r.stats.sites_added - r.stats.closing_sites, 300u);
}

}  // namespace
