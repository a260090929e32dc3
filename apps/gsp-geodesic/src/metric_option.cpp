#include "metric_option.hpp"

#include <gsp/anisotropic/metric_field.hpp>
#include <gsp/anisotropic/metric_sources.hpp>
#include <gsp/cli/app.hpp>
#include <gsp/cli/parse.hpp>
#include <gsp/errors.hpp>
#include <gsp/io/mesh_io.hpp>

#include <CLI/CLI.hpp>

namespace gsp::geodesic_app {
namespace {

constexpr const char* kOption = "--metric";

bool starts_with(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

double parse_ratio(const std::string& spec, const std::string& text) {
  const double r = cli::parse_number(text, kOption);
  if (!(r > 0)) throw cli::UsageError(std::string(kOption) + ": \"" + spec + "\": the ratio must be > 0");
  return r;
}

[[noreturn]] void bad_syntax(const std::string& spec) {
  throw cli::UsageError(std::string(kOption) + ": \"" + spec +
                        "\" is not direction=X,Y,Z:ratio=R, curvature:ratio=R[:smooth=N], attributes or a file");
}

// Per-vertex tensors of the file's vertices onto the (possibly welded) mesh's vertices: a
// welded vertex takes the tensor of the first file vertex merged into it.
anisotropic::MetricField attribute_metric(const cli::LoadedMesh& in) {
  const io::ReadResult file = io::read_mesh(in.path);
  if (!anisotropic::has_tensor_attributes(file.attributes))
    throw InvalidInput("--metric attributes: the input has no tensor_xx, tensor_xy, tensor_xz, tensor_yy, "
                       "tensor_yz, tensor_zz vertex properties");
  const anisotropic::MetricField by_file = anisotropic::metric_from_attributes(file.attributes, in.file_vertices());
  if (!in.welded) return by_file;
  anisotropic::MetricField field{anisotropic::MetricLocation::per_vertex,
                                 std::vector<anisotropic::SymmetricTensor>(in.mesh.num_vertices())};
  std::vector<bool> set(in.mesh.num_vertices(), false);
  for (std::size_t i = 0; i < in.vertex_map.size(); ++i)
    if (!set[in.vertex_map[i]]) field.tensors[in.vertex_map[i]] = by_file.tensors[i], set[in.vertex_map[i]] = true;
  return field;
}

}  // namespace

void add_metric_option(CLI::App& app, std::string& spec) {
  app.add_option(kOption, spec,
                 "propagate in a Riemannian metric: direction=X,Y,Z:ratio=R (a step along the direction "
                 "costs R), curvature:ratio=R[:smooth=N] (along the largest principal curvature, directions "
                 "smoothed over N one-rings, default 3), attributes (PLY "
                 "tensor_xx..tensor_zz vertex properties) or a text file of tensors (docs/anisotropic.md)")
      ->type_name("SPEC|FILE");
}

MetricRequest parse_metric(const std::string& spec) {
  MetricRequest r;
  r.spec = spec;
  if (spec.empty()) return r;
  if (spec == "attributes") {
    r.kind = MetricRequest::Kind::attributes;
  } else if (starts_with(spec, "direction=")) {
    const std::size_t colon = spec.find(":ratio=");
    if (colon == std::string::npos) bad_syntax(spec);
    r.kind = MetricRequest::Kind::direction;
    r.direction = cli::parse_vec3(spec.substr(10, colon - 10), kOption);
    if (!(norm(r.direction) > 0))
      throw cli::UsageError(std::string(kOption) + ": \"" + spec + "\": the direction must not be zero");
    r.ratio = parse_ratio(spec, spec.substr(colon + 7));
  } else if (starts_with(spec, "curvature")) {
    if (!starts_with(spec, "curvature:ratio=")) bad_syntax(spec);
    r.kind = MetricRequest::Kind::curvature;
    const std::size_t smooth = spec.find(":smooth=");
    r.ratio = parse_ratio(spec, spec.substr(16, smooth == std::string::npos ? std::string::npos : smooth - 16));
    if (smooth != std::string::npos) {
      const std::vector<Index> n = cli::parse_index_list(spec.substr(smooth + 8), kOption);
      if (n.size() != 1 || n[0] > 100)
        throw cli::UsageError(std::string(kOption) + ": \"" + spec + "\": smooth=N takes one count from 0 to 100");
      r.smoothing = int(n[0]);
    }
  } else {
    r.kind = MetricRequest::Kind::file;
  }
  return r;
}

void apply_metric(cli::Context& ctx, const MetricRequest& request, const cli::LoadedMesh& in, SolverOptions& so) {
  if (!request.wanted()) return;
  ctx.settings()["metric"] = request.spec;
  ctx.timer().time("metric", [&] {
    anisotropic::MetricField field;
    switch (request.kind) {
      case MetricRequest::Kind::none: break;
      case MetricRequest::Kind::file:
        field = anisotropic::read_metric_file(request.spec, in.mesh.num_vertices(), in.mesh.num_faces());
        break;
      case MetricRequest::Kind::attributes: field = attribute_metric(in); break;
      case MetricRequest::Kind::direction:
        field = anisotropic::direction_metric(in.mesh, request.direction, request.ratio);
        break;
      case MetricRequest::Kind::curvature:
        field = anisotropic::curvature_metric(in.mesh, request.ratio, request.smoothing);
        break;
    }
    so.edge_lengths = anisotropic::metric_edge_lengths(in.mesh, field);
    so.edge_lengths_line_scale = anisotropic::line_scale(field);
  });
}

}  // namespace gsp::geodesic_app
