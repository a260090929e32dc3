// gsp-layout-report: the cache layout's effect and cost on every shared mesh (after welding
// bit-identical positions, as the apps do) and on two synthetic meshes of about 100k vertices.
// Prints a Markdown table for docs/layout.md. Usage: gsp-layout-report [DATA_DIR]
#include <gsp/io/mesh_io.hpp>
#include <gsp/layout.hpp>
#include <gsp/weld.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "helpers/mesh_builders.hpp"
#include "test_data.hpp"

namespace {

const char* const kFiles[] = {
    "adis16480_sensor.stl", "armadillo_remeshed.obj", "camelhead.off", "cesium_milk_truck.glb",
    "cycloidal_drive.ply", "falconstatue.obj", "fertility.off", "manifold_offset1.obj",
    "nefertiti_lowres.obj", "newell_teapot.obj", "openscad_nonmanifold_crash.obj",
    "stanford_bunny.obj", "thingi10k_88566_fence_panels.stl", "thingi10k_99865_tires.stl"};

double median_layout_ms(const gsp::TriangleMesh& mesh) {
  std::vector<double> ms;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const gsp::Layout l = gsp::compute_cache_layout(mesh);
    const auto stop = std::chrono::steady_clock::now();
    if (l.vertex_order.size() != mesh.num_vertices()) std::abort();  // keeps the call alive
    ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2];
}

void row(const std::string& name, const gsp::TriangleMesh& mesh) {
  const double original = gsp::mean_neighbour_index_distance(mesh);
  const gsp::TriangleMesh shuffled_mesh = gsp::apply_layout(mesh, gsp::random_layout(mesh, 1));
  const gsp::TriangleMesh optimised_mesh = gsp::apply_layout(mesh, gsp::compute_cache_layout(mesh));
  const double shuffled = gsp::mean_neighbour_index_distance(shuffled_mesh);
  const double optimised = gsp::mean_neighbour_index_distance(optimised_mesh);
  std::printf("| `%s` | %zu | %.1f / %.1f / %.1f | %.2f / %.2f / %.2f | %.2f |\n", name.c_str(),
              mesh.num_vertices(), original, shuffled, optimised, gsp::mean_log_neighbour_index_distance(mesh),
              gsp::mean_log_neighbour_index_distance(shuffled_mesh),
              gsp::mean_log_neighbour_index_distance(optimised_mesh), median_layout_ms(mesh));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : gsp::test::data_dir();
  std::printf("| mesh | vertices | mean index distance: original / random / optimised "
              "| mean log2 distance: original / random / optimised | layout ms (median of 5) |\n");
  std::printf("|---|---:|---:|---:|---:|\n");
  int status = 0;
  for (const char* file : kFiles) {
    try {
      row(file, gsp::weld_vertices(gsp::io::read_mesh(dir + "/" + file).mesh).mesh);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", file, e.what());
      status = 1;
    }
  }
  row("grid(316), synthetic", gsp::test::grid(316));
  row("icosphere(7), synthetic", gsp::test::icosphere(7));
  return status;
}
