#pragma once
// Writing a distance field in the format the output path asks for.
#include <gsp/cli/app.hpp>
#include <gsp/cli/load.hpp>

#include <string>
#include <vector>

namespace gsp::geodesic_app {

// `distance` and `label` are per loaded-mesh vertex (+inf / kInvalidIndex where unreached);
// they are written in the file's own vertex order. Mesh formats store -1 for unreached
// vertices (viewers choke on infinities) and grey colours; .txt writes "inf".
// The --stats "result" section of a distance field: vertices reached and not, largest and
// mean finite distance.
void report_distances(cli::Context& ctx, const std::vector<double>& distance);

void write_field(const std::string& path, const cli::LoadedMesh& in, const std::vector<double>& distance,
                 const std::vector<Index>& label, bool with_labels, bool ascii);

}  // namespace gsp::geodesic_app
