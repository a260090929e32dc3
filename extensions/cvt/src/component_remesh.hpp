#pragma once
// One component of remesh_surface: its CVT and dual, tried again without features or from
// other initial sites where the remesh lacks the component's topology. Independent of the
// other components, so remesh_surface runs several side by side.
#include <gsp/cvt/remesh.hpp>
#include <gsp/cvt/surface.hpp>

#include <string>
#include <vector>

namespace gsp::cvt::detail {

// One component's remesh as remesh_surface puts it together: its dual or why there is none.
struct ComponentRemesh {
  bool ok = false, error = false;
  std::string why;                   // the last attempt's defects, or the error's message
  std::vector<Index> vertex_label;   // CvtResult::vertex_label
  std::size_t sites = 0;
  double energy = 0;
  std::vector<double> energy_curve;
  CvtStats cvt_stats;                // the last attempt's (its phase times: `timings` below)
  RemeshStats remesh_stats;
  TriangleMesh mesh;
  // `mesh` is the component's remesh by edge operations (edge_remesh.hpp): first
  // (RemeshMethod::edges), or where no CVT dual had its topology: no regions, no energy.
  bool by_edge_operations = false;
  // The CVT's phase times summed over every attempt (without features, from other initial
  // sites, grown), kept or not: where the component's time went.
  CvtTimings timings;
};

// The CVT and its dual, again without the features or from other initial sites where the
// remesh lacks the component's topology (SurfaceRemeshOptions::retries), and with `grow`
// (a component raised above its share) with twice the sites, twice at most, within its own
// vertex count; rep.sites is the component's share of the budget. Fills rep's orientation,
// retry and time figures; keeps nothing of the working mesh. A gsp::Error is reported in the
// result, anything else thrown. Where no attempt has the topology, the component is remeshed
// by edge operations (with SurfaceRemeshOptions::edge_operations) and kept if that has it.
// With RemeshMethod::edges the edge operations come first, the CVT only where their remesh is
// refused or below 20 degrees.
ComponentRemesh remesh_component(const TriangleMesh& input, const CvtOptions& co, const SurfaceRemeshOptions& options,
                                 ComponentReport& rep, bool grow = false);

}  // namespace gsp::cvt::detail
