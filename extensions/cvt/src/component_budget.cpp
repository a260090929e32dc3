#include "component_budget.hpp"

#include <algorithm>
#include <cmath>

namespace gsp::cvt::detail {

std::vector<std::size_t> plan_component_sites(const std::vector<ComponentBudgetItem>& items, std::size_t min_sites,
                                              double max_raise_fraction) {
  const std::size_t n = items.size();
  std::vector<std::size_t> sites(n, 0);
  std::size_t total = 0;
  std::vector<std::size_t> few;   // small shares of badly shaped components of fewer vertices than min_sites
  for (std::size_t i = 0; i < n; ++i) {
    total += items[i].share;
    if (items[i].share >= min_sites) {
      sites[i] = items[i].share;
    } else if (items[i].vertices >= min_sites) {
      sites[i] = min_sites;
    } else if (!items[i].well_shaped) {
      few.push_back(i);
    }
  }
  std::stable_sort(few.begin(), few.end(), [&](std::size_t a, std::size_t b) { return items[a].area > items[b].area; });
  const double cap = max_raise_fraction * double(total);
  double raised = 0;
  for (std::size_t i : few) {
    const std::size_t extra = min_sites - items[i].share;
    if (raised + double(extra) > cap) break;
    raised += double(extra);
    sites[i] = min_sites;
  }
  return sites;
}

}  // namespace gsp::cvt::detail
