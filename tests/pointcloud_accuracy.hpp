#pragma once
// Shared by the point-cloud accuracy tests: the mean relative error (MRE) of point-cloud GSP
// on a mesh's vertices against the mesh's exact geodesics (CGAL; mesh GSP where gsp::reference
// is not built), next to Dijkstra's on the same k-NN graph, and the two bars.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>
#include <gsp/pointcloud/point_cloud_geodesics.hpp>
#ifdef GSP_HAVE_EXACT_REFERENCE
#include <gsp/reference/exact_geodesics.hpp>
#endif

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace gsp::test {

using pointcloud::PointCloudGeodesics;
using pointcloud::PointGeodesicOptions;
using pointcloud::PointMethod;
using pointcloud::PointSource;

struct Errors {
  double gsp = 0, dijkstra = 0;
};

// The reference distances from a vertex of the mesh: exact (CGAL) where gsp::reference is
// built, else mesh GSP.
class ReferenceField {
 public:
  explicit ReferenceField(const TriangleMesh& mesh) : solver_(mesh) {}
  std::vector<double> operator()(Index v) const {
#ifdef GSP_HAVE_EXACT_REFERENCE
    return solver_.distances_from_vertex(v);
#else
    return solver_.compute({Source::at_vertex(v)}).vertex_distance;
#endif
  }

 private:
#ifdef GSP_HAVE_EXACT_REFERENCE
  mutable reference::ExactGeodesicSolver solver_;
#else
  GeodesicSolver solver_;
#endif
};

// The mesh's vertices as a point cloud (no faces, no normals).
inline TriangleMesh vertices_only(const TriangleMesh& mesh) {
  TriangleMesh cloud;
  cloud.positions = mesh.positions;
  return cloud;
}

// MRE averaged over `sources` random vertex sources; the cloud is the mesh's vertices only.
inline Errors measure(const std::string& path, int sources, PointMethod method = PointMethod::gsp) {
  const TriangleMesh mesh = io::read_mesh(path).mesh;
  const ReferenceField truth(mesh);
  const PointCloudGeodesics solver(vertices_only(mesh));
  PointGeodesicOptions gsp, dijkstra;
  gsp.method = method;
  dijkstra.method = PointMethod::dijkstra;
  SplitMix rng{77};
  Errors e;
  for (int s = 0; s < sources; ++s) {
    const Index v = Index(rng.next() % mesh.num_vertices());
    const std::vector<double> ex = truth(v);
    e.gsp += mre(solver.compute({PointSource::at_point(v)}, gsp).distance, ex) / sources;
    e.dijkstra += mre(solver.compute({PointSource::at_point(v)}, dijkstra).distance, ex) / sources;
  }
  std::printf("%-28s points %zu  MRE  point GSP (%s) %.3f%%  Dijkstra (same k-NN graph) %.3f%%\n",
              std::filesystem::path(path).filename().c_str(), mesh.num_vertices(),
              method == PointMethod::gsp ? "triangles" : "links", 100 * e.gsp, 100 * e.dijkstra);
  return e;
}

// The issue asks for MRE <= 2% and <= 1/3 of Dijkstra's on the same graph.
inline void expect_bars(const Errors& e, const std::string& name, double factor) {
  EXPECT_LT(e.gsp, 0.02) << name;
  EXPECT_LT(e.gsp, e.dijkstra / factor) << name;
}

}  // namespace gsp::test
