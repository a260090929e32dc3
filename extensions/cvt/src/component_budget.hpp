#pragma once
// How many sites each component of a whole input gets (internal; remesh_surface): its share of
// the budget by area, small shares raised to the fewest sites a component is remeshed with.
#include <cstddef>
#include <vector>

namespace gsp::cvt::detail {

struct ComponentBudgetItem {
  std::size_t share = 0;      // sites by area
  std::size_t vertices = 0;   // the component's own vertex count
  double area = 0;
  bool well_shaped = false;   // no angle below the quality floor: nothing to gain from few vertices
};

// Sites per component, 0 for one to keep as it is. A share of min_sites or more is kept; a
// smaller one is raised to min_sites where the component has at least min_sites vertices (kept,
// it would add them all to the output), and else, unless it is well shaped already, while the
// sites so added stay within max_raise_fraction of the shares' total (largest areas first). The other components keep
// their shares: a few percent fewer sites can change a CVT's outcome at places, so the small
// components' sites are added to the budget rather than taken from it.
std::vector<std::size_t> plan_component_sites(const std::vector<ComponentBudgetItem>& items, std::size_t min_sites,
                                              double max_raise_fraction);

}  // namespace gsp::cvt::detail
