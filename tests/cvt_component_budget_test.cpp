// Sites per component of a whole input (extensions/cvt/src/component_budget.*): shares kept,
// small shares raised to the fewest sites where the component has that many vertices, and
// within the cap (largest areas first) where it has fewer.
#include "component_budget.hpp"

#include <gtest/gtest.h>

namespace {

using gsp::cvt::detail::ComponentBudgetItem;
using gsp::cvt::detail::plan_component_sites;

TEST(CvtComponentBudget, SharesKeptSmallOnesRaisedOrKept) {
  const std::vector<ComponentBudgetItem> items = {
      {900, 5000, 90.0},   // large: its share
      {5, 300, 0.5},       // small share, many vertices: raised
      {2, 8, 0.2},         // few vertices: raised within the cap (largest area first)
      {3, 8, 0.3},
      {1, 4, 0.1},         // no room left
  };
  // Shares total 911; 5% of it is 45.55: 17 + 18 fit, then 19 more do not.
  const std::vector<std::size_t> s = plan_component_sites(items, 20, 0.05);
  ASSERT_EQ(s.size(), items.size());
  EXPECT_EQ(s[0], 900u);
  EXPECT_EQ(s[1], 20u);
  EXPECT_EQ(s[2], 20u);
  EXPECT_EQ(s[3], 20u);
  EXPECT_EQ(s[4], 0u);
}

TEST(CvtComponentBudget, WellShapedComponentsOfFewVerticesAreKept) {
  const std::vector<ComponentBudgetItem> items = {{100, 1000, 1.0}, {2, 8, 0.2, true}, {2, 8, 0.1, false}};
  EXPECT_EQ(plan_component_sites(items, 20, 1.0), (std::vector<std::size_t>{100, 0, 20}));
}

TEST(CvtComponentBudget, NoCapKeepsEveryComponentOfFewVertices) {
  const std::vector<ComponentBudgetItem> items = {{100, 1000, 1.0}, {19, 19, 0.19}, {19, 20, 0.19}, {0, 3, 0.0}};
  const std::vector<std::size_t> s = plan_component_sites(items, 20, 0.0);
  EXPECT_EQ(s, (std::vector<std::size_t>{100, 0, 20, 0}));
}

}  // namespace
