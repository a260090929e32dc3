#include "output.hpp"

#include <gsp/io/colormap.hpp>
#include <gsp/io/mesh_io.hpp>

#include <algorithm>
#include <cmath>

namespace gsp::geodesic_app {

void write_field(const std::string& path, const cli::LoadedMesh& in, const std::vector<double>& distance,
                 const std::vector<Index>& label, bool with_labels, bool ascii) {
  const std::vector<double> values = in.to_file_order(distance);
  if (io::format_from_path(path) == io::Format::txt) {
    io::write_values_txt(path, values);
    return;
  }
  io::VertexAttributes attributes;
  std::vector<float> stored(values.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    stored[i] = std::isfinite(values[i]) ? float(values[i]) : -1.0f;
  attributes.scalars.push_back({"distance", stored});
  if (io::format_from_path(path) == io::Format::ply)
    attributes.scalars.push_back({"quality", stored});   // MeshLab colours and filters by quality
  attributes.colors = io::colorize(values);
  if (with_labels) {
    const std::vector<Index> file_labels = in.to_file_order(label);
    std::vector<std::int32_t> ints(file_labels.size());
    for (std::size_t i = 0; i < ints.size(); ++i)
      ints[i] = file_labels[i] == kInvalidIndex ? -1 : std::int32_t(file_labels[i]);
    attributes.labels.push_back({"source", ints});
  }
  io::WriteOptions options;
  options.ascii = ascii;
  io::write_mesh(path, in.file_mesh(), attributes, options);
}

void report_distances(cli::Context& ctx, const std::vector<double>& distance) {
  std::size_t reached = 0;
  double max_d = 0, sum = 0;
  for (double d : distance)
    if (std::isfinite(d)) ++reached, sum += d, max_d = std::max(max_d, d);
  cli::Json& res = ctx.stats()["result"];
  res["vertices_reached"] = reached;
  res["vertices_unreached"] = distance.size() - reached;
  res["max_distance"] = max_d;
  res["mean_distance"] = reached ? sum / double(reached) : 0.0;
}

}  // namespace gsp::geodesic_app
