// Independent queries in parallel give exactly the sequential results; the matrix mode and
// error propagation.
#include "helpers/geodesic_fixtures.hpp"

#include <gsp/available_memory.hpp>
#include <gsp/batch.hpp>
#include <gsp/errors.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace gsp::test {
namespace {

TEST(Batch, ParallelQueriesEqualSequentialOnes) {
  const TriangleMesh m = icosphere(4);
  const GeodesicSolver solver(m);
  std::vector<std::vector<Source>> queries;
  for (Index v = 0; v < 16; ++v) queries.push_back({Source::at_vertex(v * 97 % Index(m.num_vertices()))});
  queries.push_back({Source::at_vertex(1), Source::at_vertex(500)});
  for (unsigned threads : {1u, 2u, 4u}) {
    const auto results = compute_many(solver, queries, {}, threads);
    ASSERT_EQ(results.size(), queries.size());
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const auto expect = solver.compute(queries[q]).vertex_distance;
      ASSERT_EQ(results[q].vertex_distance, expect) << "query " << q << " threads " << threads;
    }
  }
}

TEST(Batch, DistanceMatrixRowsAreFieldsAndNearlySymmetric) {
  const TriangleMesh m = icosphere(3);
  const GeodesicSolver solver(m);
  const std::vector<Index> vs = {0, 17, 100, 250, 600};
  const auto matrix = distance_matrix(solver, vs, {}, 2);
  for (std::size_t i = 0; i < vs.size(); ++i) {
    const auto row = solver.compute({Source::at_vertex(vs[i])}).vertex_distance;
    for (std::size_t j = 0; j < vs.size(); ++j) {
      EXPECT_EQ(matrix[i * vs.size() + j], row[vs[j]]);
      EXPECT_NEAR(matrix[i * vs.size() + j], matrix[j * vs.size() + i], 0.02 * (1 + row[vs[j]]));
    }
    EXPECT_EQ(matrix[i * vs.size() + i], 0.0);
  }
}

TEST(Batch, ErrorsReachTheCaller) {
  const GeodesicSolver solver(grid(4));
  EXPECT_THROW(compute_many(solver, {{Source::at_vertex(0)}, {Source::at_vertex(999)}}, {}, 2), InvalidInput);
  EXPECT_EQ(resolve_threads(8, 3), 3u);
  EXPECT_GE(resolve_threads(0, 100), 1u);
}

// A matrix no machine holds (400,000 rows: 1.3 TB) is refused before any query runs, with the
// sizes; available_memory() reads this machine's.
TEST(Batch, AMatrixBeyondTheMemoryIsRefused) {
  ASSERT_GT(available_memory(), 0u);
  const GeodesicSolver solver(grid(4));
  const std::vector<Index> vertices(400000, 0);
  try {
    distance_matrix(solver, vertices);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("a 400000 x 400000 distance matrix: about 1.28e+03 GB needed"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace gsp::test
