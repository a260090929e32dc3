// The only translation unit that instantiates CGAL's Heat_method_3 (needs CGAL_EIGEN3_ENABLED).
#include <gsp/reference/heat_method.hpp>

#include "manifold_surface.hpp"
#include "source_checks.hpp"

#include <gsp/adapters/cgal.hpp>
#include <gsp/errors.hpp>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/exceptions.h>

#include <limits>
#include <string>

namespace gsp::reference {

namespace {

using adapters::CgalSurfaceMesh;
using VertexIndex = CgalSurfaceMesh::Vertex_index;
namespace HM = CGAL::Heat_method_3;
using DirectSolver = HM::Surface_mesh_geodesic_distances_3<CgalSurfaceMesh, HM::Direct>;
using IdtSolver = HM::Surface_mesh_geodesic_distances_3<CgalSurfaceMesh, HM::Intrinsic_Delaunay>;

constexpr double kInf = std::numeric_limits<double>::infinity();

// One heat solver per connected component: the Poisson step determines distances only up to
// a constant per component, which CGAL fixes from the sources, so a component without a
// source would get meaningless values. Heap-allocated: the solver refers to `mesh`.
struct ComponentSolver {
  CgalSurfaceMesh mesh;
  std::unique_ptr<DirectSolver> direct;
  std::unique_ptr<IdtSolver> idt;
  CgalSurfaceMesh::Property_map<VertexIndex, double> distance;  // written by each solve
};

template <class Solver>
void solve_component(Solver& solver, ComponentSolver& comp, const std::vector<Index>& local_sources) {
  solver.clear_sources();
  for (Index v : local_sources) solver.add_source(VertexIndex(v));
  solver.estimate_geodesic_distances(comp.distance);
}

}  // namespace

struct HeatMethodSolver::Impl {
  HeatMethodMode mode;
  detail::ManifoldSurface surface;
  std::vector<std::unique_ptr<ComponentSolver>> components;
};

HeatMethodSolver::HeatMethodSolver(const TriangleMesh& mesh, HeatMethodMode mode)
    : impl_(std::make_unique<Impl>()) {
  impl_->mode = mode;
  impl_->surface = detail::make_manifold_surface(mesh);
  try {
    for (detail::SurfaceComponent& part : impl_->surface.components) {
      auto comp = std::make_unique<ComponentSolver>();
      adapters::ToCgalResult converted = adapters::to_cgal(part.mesh);
      if (!converted.skipped_faces.empty())
        throw TopologyError("CGAL's Surface_mesh refused input face " +
                            std::to_string(part.faces[converted.skipped_faces.front()]) +
                            " (non-manifold configuration)");
      comp->mesh = std::move(converted.mesh);
      comp->distance = comp->mesh.add_property_map<VertexIndex, double>("v:gsp_distance", 0.0).first;
      if (mode == HeatMethodMode::direct)
        comp->direct = std::make_unique<DirectSolver>(comp->mesh);
      else
        comp->idt = std::make_unique<IdtSolver>(comp->mesh);
      part.mesh = TriangleMesh{};
      impl_->components.push_back(std::move(comp));
    }
  } catch (const CGAL::Failure_exception& e) {
    throw Error(std::string("CGAL heat method precomputation failed: ") + e.what());
  }
}

HeatMethodSolver::~HeatMethodSolver() = default;
HeatMethodSolver::HeatMethodSolver(HeatMethodSolver&&) noexcept = default;
HeatMethodSolver& HeatMethodSolver::operator=(HeatMethodSolver&&) noexcept = default;

std::vector<double> HeatMethodSolver::solve(const std::vector<Index>& source_vertices) {
  if (source_vertices.empty()) throw InvalidInput("the heat method needs at least one source");
  Impl& m = *impl_;
  const detail::ManifoldSurface& s = m.surface;
  for (Index v : source_vertices) detail::check_vertex_index(v, s.num_input_vertices);

  std::vector<std::vector<Index>> local_sources(m.components.size());
  for (Index v : source_vertices)
    if (s.vertex_component[v] != kInvalidIndex)
      local_sources[s.vertex_component[v]].push_back(s.vertex_local[v]);

  std::vector<double> out(s.num_input_vertices, kInf);
  try {
    for (std::size_t c = 0; c < m.components.size(); ++c) {
      if (local_sources[c].empty()) continue;
      ComponentSolver& comp = *m.components[c];
      if (comp.direct)
        solve_component(*comp.direct, comp, local_sources[c]);
      else
        solve_component(*comp.idt, comp, local_sources[c]);
      const auto& local_to_input = s.components[c].vertices;
      for (std::size_t v = 0; v < local_to_input.size(); ++v)
        out[local_to_input[v]] = comp.distance[VertexIndex(static_cast<Index>(v))];
    }
  } catch (const CGAL::Failure_exception& e) {
    throw Error(std::string("CGAL heat method solve failed: ") + e.what());
  }
  for (Index v : source_vertices)
    if (s.vertex_component[v] == kInvalidIndex) out[v] = 0.0;
  return out;
}

HeatMethodMode HeatMethodSolver::mode() const { return impl_->mode; }
std::size_t HeatMethodSolver::num_vertices() const { return impl_->surface.num_input_vertices; }
std::size_t HeatMethodSolver::num_components() const { return impl_->components.size(); }

std::vector<double> heat_method_distances(const TriangleMesh& mesh,
                                          const std::vector<Index>& source_vertices,
                                          HeatMethodMode mode) {
  HeatMethodSolver solver(mesh, mode);
  return solver.solve(source_vertices);
}

}  // namespace gsp::reference
