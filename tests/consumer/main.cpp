// A program a user would write against the installed package: a flat grid, distances from a
// corner (on a plane they are the straight-line distances), written to PLY and read back.
#include <gsp/geodesics.hpp>
#include <gsp/io/mesh_io.hpp>

#include <cmath>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer OUTPUT.ply\n");
    return 2;
  }
  const int n = 12;   // (n+1)^2 vertices on the unit square
  gsp::TriangleMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) mesh.positions.push_back({double(i) / n, double(j) / n, 0.0});
  auto id = [&](int i, int j) { return gsp::Index(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }

  const gsp::GeodesicResult result = gsp::geodesic_distances(mesh, {gsp::Source::at_vertex(0)});
  double worst = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double straight = gsp::distance(mesh.positions[0], mesh.positions[v]);
    worst = std::fmax(worst, std::fabs(result.vertex_distance[v] - straight));
  }
  if (!(worst < 1e-6)) {
    std::fprintf(stderr, "distance off the straight line on a plane by %g\n", worst);
    return 1;
  }

  gsp::io::VertexAttributes attributes;
  attributes.scalars.emplace_back("distance", std::vector<float>(result.vertex_distance.begin(),
                                                                 result.vertex_distance.end()));
  gsp::io::write_mesh(argv[1], mesh, attributes);
  const gsp::io::ReadResult back = gsp::io::read_mesh(argv[1]);
  if (back.mesh.num_vertices() != mesh.num_vertices() || back.mesh.num_faces() != mesh.num_faces() ||
      back.attributes.scalars.size() != 1) {
    std::fprintf(stderr, "the PLY did not read back\n");
    return 1;
  }
  std::printf("consumer: %zu vertices, max deviation %.3g, PLY round trip ok\n",
              mesh.num_vertices(), worst);
  return 0;
}
