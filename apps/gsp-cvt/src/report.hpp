#pragma once
// What gsp-cvt writes besides the remeshed surface: the --stats sections and the regions file.
#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>
#include <gsp/cvt/cvt.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/cvt/remesh.hpp>
#include <gsp/topology.hpp>

namespace gsp::cvt_app {

void report_cvt(cli::Context& ctx, const cvt::CvtResult& cvt);
void report_remesh(cli::Context& ctx, const cvt::RemeshResult& remesh, const TopologyReport& input,
                   const TopologyReport& output);
void report_quality(cli::Context& ctx, const cvt::MeshQuality& q, const cvt::HausdorffDistance& h);

// The input mesh (file vertices) with an int `label` per vertex and a colour per region.
void write_regions(const std::string& path, const cli::LoadedMesh& in, const cvt::CvtResult& cvt);

}  // namespace gsp::cvt_app
