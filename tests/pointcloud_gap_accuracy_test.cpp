// Point-cloud GSP where the k-NN graph links sheets closer than the sample spacing: the
// vertices of camelhead, whose lips nearly touch (docs/pointcloud.md, gap links). A binary of
// its own: 5 exact fields on 11k vertices take about half of the 20 s a test binary may use.
#include "pointcloud_accuracy.hpp"
#include "test_data.hpp"

#include <gtest/gtest.h>

namespace gsp::test {
namespace {

// Camelhead's lips are closer than its sample spacing: k-NN links cross the mouth slit, and
// before the gap rule (docs/pointcloud.md) the first of these sources had 2.26% and 1.8x. Over
// 5 sources: 0.81%, 3.56x (the first alone: 1.90%, 2.1x, still the worst).
TEST(PointCloudGapAccuracy, CamelheadAcrossTheMouth) {
  if (!have_shared_data()) GTEST_SKIP() << "shared meshes not found";
  expect_bars(measure(shared_mesh("camelhead.off"), 5), "camelhead", 3.0);
}

}  // namespace
}  // namespace gsp::test
