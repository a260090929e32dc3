// The only translation unit that instantiates CGAL's Surface_mesh_shortest_path.
#include <gsp/reference/exact_geodesics.hpp>

#include "manifold_surface.hpp"
#include "source_checks.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/exceptions.h>

#include <limits>
#include <string>

namespace gsp::reference {

namespace {

using adapters::CgalKernel;
using adapters::CgalSurfaceMesh;
using Traits = CGAL::Surface_mesh_shortest_path_traits<CgalKernel, CgalSurfaceMesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
using VertexIndex = CgalSurfaceMesh::Vertex_index;
using FaceIndex = CgalSurfaceMesh::Face_index;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Heap-allocated so that `paths`, which keeps a reference to `mesh`, never sees it move.
struct ComponentSolver {
  CgalSurfaceMesh mesh;
  std::unique_ptr<ShortestPath> paths;
  bool has_sources = false;
};

}  // namespace

struct ExactGeodesicSolver::Impl {
  detail::ManifoldSurface surface;
  std::vector<Triangle> input_triangles;  // to map barycentric weights onto CGAL's corner order
  std::vector<std::unique_ptr<ComponentSolver>> components;
  std::vector<Index> isolated_sources;    // isolated vertices in the current source set

  // CGAL orders a face's barycentric coordinates as source(halfedge(f)), target(halfedge(f)),
  // target(next(halfedge(f))); our weights follow the input face's corners.
  Traits::Barycentric_coordinates to_cgal(Index face, const std::array<double, 3>& w) const {
    const Index c = surface.face_component[face];
    const ComponentSolver& comp = *components[c];
    const auto& local_to_input = surface.components[c].vertices;
    const FaceIndex f(surface.face_local[face]);
    const auto h = comp.mesh.halfedge(f);
    const VertexIndex corners[3] = {comp.mesh.source(h), comp.mesh.target(h),
                                    comp.mesh.target(comp.mesh.next(h))};
    const Triangle& t = input_triangles[face];
    Traits::Barycentric_coordinates b{};
    for (int j = 0; j < 3; ++j) {
      const Index v = local_to_input[static_cast<std::size_t>(corners[j])];
      b[j] = t[0] == v ? w[0] : (t[1] == v ? w[1] : w[2]);
    }
    return b;
  }

  static double finite_or_inf(double d) { return d < 0 ? kInf : d; }
};

ExactGeodesicSolver::ExactGeodesicSolver(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->surface = detail::make_manifold_surface(mesh);
  impl_->input_triangles = mesh.triangles;
  for (detail::SurfaceComponent& part : impl_->surface.components) {
    auto comp = std::make_unique<ComponentSolver>();
    adapters::ToCgalResult converted = adapters::to_cgal(part.mesh);
    // make_manifold_surface has refused everything a halfedge structure cannot hold; a skipped
    // face here would be a gap in those checks, so say so rather than lose the face silently.
    if (!converted.skipped_faces.empty())
      throw TopologyError("CGAL's Surface_mesh refused input face " +
                          std::to_string(part.faces[converted.skipped_faces.front()]) +
                          " (non-manifold configuration)");
    comp->mesh = std::move(converted.mesh);
    comp->paths = std::make_unique<ShortestPath>(comp->mesh);
    part.mesh = TriangleMesh{};  // the CGAL copy is all that is needed from here on
    impl_->components.push_back(std::move(comp));
  }
}

ExactGeodesicSolver::~ExactGeodesicSolver() = default;
ExactGeodesicSolver::ExactGeodesicSolver(ExactGeodesicSolver&&) noexcept = default;
ExactGeodesicSolver& ExactGeodesicSolver::operator=(ExactGeodesicSolver&&) noexcept = default;

void ExactGeodesicSolver::set_sources(const std::vector<ExactSource>& sources) {
  if (sources.empty()) throw InvalidInput("exact geodesics need at least one source");
  Impl& m = *impl_;
  const detail::ManifoldSurface& s = m.surface;
  // Check everything before touching the solvers, so a bad source leaves the old set intact.
  std::vector<Traits::Barycentric_coordinates> locations(sources.size());
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const ExactSource& src = sources[i];
    if (src.is_vertex()) {
      detail::check_vertex_index(src.element, s.num_input_vertices);
    } else {
      const auto w = detail::checked_barycentric(src.element, s.num_input_faces, src.barycentric);
      locations[i] = m.to_cgal(src.element, w);
    }
  }
  m.isolated_sources.clear();
  for (auto& comp : m.components) {
    comp->paths->clear();
    comp->has_sources = false;
  }
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const ExactSource& src = sources[i];
    if (src.is_vertex()) {
      const Index c = s.vertex_component[src.element];
      if (c == kInvalidIndex) {
        m.isolated_sources.push_back(src.element);
        continue;
      }
      m.components[c]->paths->add_source_point(VertexIndex(s.vertex_local[src.element]));
      m.components[c]->has_sources = true;
    } else {
      const Index c = s.face_component[src.element];
      m.components[c]->paths->add_source_point(FaceIndex(s.face_local[src.element]), locations[i]);
      m.components[c]->has_sources = true;
    }
  }
  try {
    for (auto& comp : m.components)
      if (comp->has_sources) comp->paths->build_sequence_tree();
  } catch (const CGAL::Failure_exception& e) {
    throw Error(std::string("CGAL shortest paths failed: ") + e.what());
  }
}

std::vector<double> ExactGeodesicSolver::vertex_distances() const {
  const Impl& m = *impl_;
  std::vector<double> out(m.surface.num_input_vertices, kInf);
  for (std::size_t c = 0; c < m.components.size(); ++c) {
    ComponentSolver& comp = *m.components[c];
    if (!comp.has_sources) continue;
    const auto& local_to_input = m.surface.components[c].vertices;
    for (std::size_t v = 0; v < local_to_input.size(); ++v)
      out[local_to_input[v]] = Impl::finite_or_inf(
          comp.paths->shortest_distance_to_source_points(VertexIndex(static_cast<Index>(v))).first);
  }
  for (Index v : m.isolated_sources) out[v] = 0.0;
  return out;
}

double ExactGeodesicSolver::distance_to_vertex(Index v) const {
  const Impl& m = *impl_;
  detail::check_vertex_index(v, m.surface.num_input_vertices);
  const Index c = m.surface.vertex_component[v];
  if (c == kInvalidIndex) {
    for (Index s : m.isolated_sources)
      if (s == v) return 0.0;
    return kInf;
  }
  ComponentSolver& comp = *m.components[c];
  if (!comp.has_sources) return kInf;
  return Impl::finite_or_inf(
      comp.paths->shortest_distance_to_source_points(VertexIndex(m.surface.vertex_local[v])).first);
}

double ExactGeodesicSolver::distance_to_point(Index face, const std::array<double, 3>& barycentric) const {
  const Impl& m = *impl_;
  const auto w = detail::checked_barycentric(face, m.surface.num_input_faces, barycentric);
  ComponentSolver& comp = *m.components[m.surface.face_component[face]];
  if (!comp.has_sources) return kInf;
  return Impl::finite_or_inf(comp.paths
                                 ->shortest_distance_to_source_points(
                                     FaceIndex(m.surface.face_local[face]), m.to_cgal(face, w))
                                 .first);
}

std::vector<double> ExactGeodesicSolver::distances(const std::vector<ExactSource>& sources) {
  set_sources(sources);
  return vertex_distances();
}

std::size_t ExactGeodesicSolver::num_vertices() const { return impl_->surface.num_input_vertices; }
std::size_t ExactGeodesicSolver::num_components() const { return impl_->components.size(); }
std::size_t ExactGeodesicSolver::isolated_vertices() const { return impl_->surface.isolated_vertices; }
std::size_t ExactGeodesicSolver::flipped_faces() const { return impl_->surface.flipped_faces; }

std::vector<double> exact_geodesic_distances(const TriangleMesh& mesh,
                                             const std::vector<ExactSource>& sources) {
  ExactGeodesicSolver solver(mesh);
  return solver.distances(sources);
}

}  // namespace gsp::reference
