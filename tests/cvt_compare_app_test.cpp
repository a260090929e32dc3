// gsp-cvt-compare end to end: a method that cannot run is a row with its reason, never the
// end of the run (scripts/cvt_corpus.py relies on it), and the other method's row is kept.
#include "apps_support.hpp"

#include <gtest/gtest.h>

namespace {

using namespace gsp::test;

const std::string kApp = bin("gsp-cvt-compare");

// A tetrahedron and, beside it, two faces on the same three vertices folded onto each other
// (a soup's back-to-back duplicate): CGAL's isotropic_remeshing crashes on the pair, so its
// row says it was not run; gsp-cvt remeshes the tetrahedron and keeps the pair's one face
// (the other, on the same three vertices, is left out: cvt::drop_duplicate_faces).
TEST(CvtCompareApp, FoldedFacePairIsARowNotACrash) {
  ScratchDir dir("cvtcmp");
  write_file(dir / "in.obj",
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 3 0 0\nv 4 0 0\nv 3 1 0\n"
             "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\nf 5 6 7\nf 5 7 6\n");
  const RunResult r = run(kApp + " " + quote((dir / "in.obj").string()) +
                              " --vertices 60 --count-runs 1 --hausdorff-samples 2000 --stats -",
                          dir, 120);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("| CGAL isotropic_remeshing | failed: not run: 3 edges between two faces on the same three vertices"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| gsp-cvt (Lloyd + restricted Delaunay) | "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| gsp-cvt (Lloyd + restricted Delaunay) | failed"), std::string::npos) << r.out;

  // The pair's share of the budget is too small (kept as it is, after the tetrahedron's
  // remesh): its one triangle left is counted apart from the remesh's own.
  const std::size_t json_start = r.out.find('{');
  ASSERT_NE(json_start, std::string::npos) << r.out;
  const JsonValue stats = parse_json(r.out.substr(json_start));
  const JsonValue& gsp = stats["rows"].items.at(0)["measures"];
  EXPECT_EQ(gsp["remeshed_faces"].num + 1, gsp["faces"].num);
  EXPECT_GE(gsp["remeshed_min_angle"].num, gsp["min_angle"].num);
  EXPECT_GT(gsp["remeshed_min_angle"].num, 20.0);
}

}  // namespace
