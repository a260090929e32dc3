#include "measure.hpp"

#include <gsp/cli/topology_json.hpp>
#include <gsp/connectivity.hpp>
#include <gsp/cvt/closest_point_index.hpp>
#include <gsp/cvt/components.hpp>
#include <gsp/cvt/features.hpp>
#include <gsp/cvt/quality.hpp>
#include <gsp/errors.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gsp::cvt_compare {

namespace {

// The shared topology figures plus the duplicate vertices a remesh must not have.
cli::Json topology_with_duplicates(const TopologyReport& t, std::size_t duplicates) {
  cli::Json j = cli::topology_json(t);
  j["duplicate_vertices"] = duplicates;
  return j;
}

// Points along the feature edges, about diagonal / 2000 apart (every edge's ends and
// midpoint at least), at most ~200,000.
std::vector<Vec3> feature_samples(const TriangleMesh& m, const cvt::Features& f) {
  double total = 0;
  for (const auto& e : f.edges) total += distance(m.positions[e[0]], m.positions[e[1]]);
  const double step = std::max(bounding_box(m).diagonal() / 2000, total / 200000);
  std::vector<Vec3> out;
  for (const auto& e : f.edges) {
    const Vec3 a = m.positions[e[0]], b = m.positions[e[1]];
    const int n = std::max(2, int(std::ceil(distance(a, b) / step)));
    for (int i = 0; i <= n; ++i) out.push_back(a + (double(i) / n) * (b - a));
  }
  return out;
}

}  // namespace

cli::Json describe_input(const TriangleMesh& input) {
  cli::Json j = topology_with_duplicates(analyze_topology(input, build_connectivity(input)), cvt::duplicate_vertices(input));
  std::size_t surfaces = 0;
  for (const TriangleMesh& c : cvt::split_components(input).meshes) {
    const cvt::ComponentTopology t = cvt::component_topology(c);
    if (t.report.is_manifold() && t.orientable) ++surfaces;
  }
  j["surface_components"] = surfaces;
  j["feature_edges"] = cvt::detect_features(input).edges.size();
  return j;
}

Measures measure_output(const TriangleMesh& input, const TriangleMesh& output, std::size_t hausdorff_samples) {
  Measures m;
  m.topology = analyze_topology(output, build_connectivity(output));
  m.duplicate_vertices = cvt::duplicate_vertices(output);
  const cvt::MeshQuality q = cvt::measure_mesh_quality(output);
  m.min_angle = q.min_angle;
  m.mean_min_angle = q.mean_min_angle;
  m.percent_below_30 = 100 * q.below_30;
  m.mean_aspect_ratio = q.mean_aspect_ratio;
  m.degenerate = q.degenerate;
  try {
    cvt::HausdorffOptions ho;
    ho.samples = hausdorff_samples;
    m.hausdorff_percent = 100 * cvt::hausdorff_distance(input, output, ho).relative;
  } catch (const InvalidInput&) {
  }
  const cvt::Features features = cvt::detect_features(input);
  if (!features.edges.empty() && output.num_faces() > 0) {
    try {
      const cvt::ClosestPointIndex index(output);
      double worst = 0;
      for (const Vec3& p : feature_samples(input, features)) worst = std::max(worst, index.closest(p).distance);
      m.feature_distance_percent = 100 * worst / bounding_box(input).diagonal();
    } catch (const InvalidInput&) {
    }
  }
  // Against the surface the input describes: where fans of faces only touch at a vertex, no
  // manifold output can keep that vertex, so the reference has it split (one per fan).
  m.topology_kept = cvt::same_topology_per_component(cvt::described_surface(input), output, &m.topology_difference);
  return m;
}

cli::Json to_json(const Measures& m) {
  cli::Json j = topology_with_duplicates(m.topology, m.duplicate_vertices);
  j["min_angle"] = m.min_angle;
  j["mean_min_angle"] = m.mean_min_angle;
  j["percent_below_30"] = m.percent_below_30;
  j["mean_aspect_ratio"] = m.mean_aspect_ratio;
  j["degenerate_triangles"] = m.degenerate;
  j["hausdorff_percent_of_diagonal"] = m.hausdorff_percent;
  j["feature_distance_percent_of_diagonal"] = m.feature_distance_percent;
  j["topology_kept"] = m.topology_kept;
  j["topology_difference"] = m.topology_difference;
  return j;
}

}  // namespace gsp::cvt_compare
