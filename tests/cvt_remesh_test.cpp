// gsp::cvt remeshing of closed meshes: genus 4 (fertility) and genus 0 (armadillo).
#include "cvt_remesh_check.hpp"

namespace {

using namespace gsp;
using test::check_remesh;

TEST(CvtRemesh, FertilityGenus4) {
  const TriangleMesh m = io::read_mesh(std::string(GSP_TEST_DIR) + "/../data/samples/fertility.off").mesh;
  check_remesh(m, 2000, {29.0, 0.001, 0.010});   // measured 31.3, 0%
}

TEST(CvtRemesh, ArmadilloGenus0) {
  if (!test::have_shared_data()) GTEST_SKIP() << "no shared meshes";
  check_remesh(io::read_mesh(test::shared_mesh("armadillo_remeshed.obj")).mesh, 2000, {28.0, 0.001, 0.011});   // 31.7, 0%
}

}  // namespace
