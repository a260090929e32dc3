#pragma once
// What gsp-cvt writes besides the remeshed surface: the --stats sections and the regions file.
#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/cvt/surface.hpp>
#include <gsp/topology.hpp>

namespace gsp::cvt_app {

void report_cvt(cli::Context& ctx, const cvt::SurfaceRemeshResult& r);
// Also the per-component outcomes ("components": input faces, sites, outcome, reason).
void report_remesh(cli::Context& ctx, const cvt::SurfaceRemeshResult& r, const TopologyReport& input,
                   const TopologyReport& output);
// A note per component kept as it is (the first 20, then a count). Throws gsp::Error when no
// component could be remeshed: the output would be the input.
void note_kept_components(cli::Context& ctx, const cvt::SurfaceRemeshResult& r);
void report_quality(cli::Context& ctx, const cvt::MeshQuality& q, const cvt::HausdorffDistance& h);

// The input mesh (file vertices) with an int `label` per vertex and a colour per region.
// `labels`: per mesh vertex (kInvalidIndex: none).
void write_regions(const std::string& path, const cli::LoadedMesh& in, const std::vector<Index>& labels);

}  // namespace gsp::cvt_app
