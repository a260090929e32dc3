// gsp::cvt remeshing of meshes with boundary: a disk (camelhead), a scan with five holes
// (bunny), a flat square.
#include "cvt_meshes.hpp"
#include "cvt_remesh_check.hpp"

namespace {

using namespace gsp;
using test::check_remesh;

TEST(CvtRemesh, CamelheadDisk) {
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  check_remesh(io::read_mesh(test::shared_mesh("camelhead.off")).mesh, 2000, {12.0, 0.004, 0.013});
}

TEST(CvtRemesh, BunnyFiveHoles) {
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  check_remesh(io::read_mesh(test::shared_mesh("stanford_bunny.obj")).mesh, 2000, {13.0, 0.003, 0.011});
}

TEST(CvtRemesh, FlatSquare) {
  // A flat disk whose boundary has four corners (cut off by the dual: corners are not kept,
  // which is most of the Hausdorff distance here).
  const TriangleMesh m = test::square_grid(30);
  check_remesh(m, 200, {20.0, 0.02, 0.03});
}

}  // namespace
