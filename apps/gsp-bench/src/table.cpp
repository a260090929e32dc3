#include "table.hpp"

#include "format.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace gsp::bench {

namespace {

void appendf(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void appendf(std::string& out, const char* format, ...) {
  char buf[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buf, sizeof buf, format, args);
  va_end(args);
  out += buf;
}

double time_of(const MeshRun& run, Method id) {
  for (const MethodRun& m : run.methods)
    if (m.method.id == id && m.ok()) return summarise(run, m).query_s;
  return std::nan("");
}

double mre_of(const MeshRun& run, Method id) {
  for (const MethodRun& m : run.methods)
    if (m.method.id == id && m.ok()) return summarise(run, m).mre;
  return std::nan("");
}

// --domain points: the figures per mesh: the MRE of point-cloud GSP (on the local
// triangles, and over the graph's links when measured) and of Dijkstra on the same k-NN
// graph against the mesh's exact geodesics, their ratio, and point-cloud GSP's query time
// over mesh GSP's.
std::string points_section(const Report& report) {
  bool any = false;
  for (const MeshRun& run : report.runs)
    for (const MethodRun& m : run.methods) any = any || (is_points(m.method.id) && m.ok());
  if (!any) return "";
  std::string out = "point clouds (the mesh's vertices, k-NN graph)\n";
  appendf(out, "  %-28s %12s %12s %12s %16s %16s\n", "mesh", "MRE gsp", "MRE graph", "MRE dijkstra", "dijkstra / gsp",
          "time / mesh gsp");
  for (const MeshRun& run : report.runs) {
    const double g = mre_of(run, Method::points_gsp), d = mre_of(run, Method::points_dijkstra);
    const double graph = mre_of(run, Method::points_graph_gsp);
    appendf(out, "  %-28s", run.mesh->name.c_str());
    out += " " + cell(100 * g, 11, "%.3f") + "%" + " " + cell(100 * graph, 11, "%.3f") + "%" + " " +
           cell(100 * d, 11, "%.3f") + "%" + " " + cell(d / g, 16, "%.2f") + " " +
           cell(time_of(run, Method::points_gsp) / time_of(run, Method::gsp), 16, "%.2f") + "\n";
  }
  return out + "\n";
}

// The physical bounds (bounds.hpp): how far below the straight line and above the edge path
// the worst vertex is, in %, and how many vertices break a bound by more than 1% or are NaN.
std::string bound_cells(const Summary& s) {
  const bool on = s.bound_sources > 0;
  const double bad = double(s.bounds.below_count + s.bounds.above_count + s.bounds.nan);
  return cell(on ? 100 * s.bounds.below_line : NAN, 8, "%.4f") + " " +
         cell(on ? 100 * s.bounds.above_edge : NAN, 8, "%.4f") + " " + cell(on ? bad : NAN, 6, "%.0f");
}

struct GeoMean {
  double log_sum = 0;
  int n = 0;
  void add(double r) {
    if (std::isfinite(r) && r > 0) log_sum += std::log(r), ++n;
  }
  double value() const { return n ? std::exp(log_sum / n) : std::nan(""); }
};

}  // namespace

std::string format_table(const Report& report) {
  std::string out;
  for (const MeshRun& run : report.runs) {
    const BenchMesh& m = *run.mesh;
    appendf(out, "%s: %zu vertices, %zu faces, %zu sources, exact references %zu (%zu from cache)\n",
            m.name.c_str(), m.mesh.num_vertices(), m.mesh.num_faces(), run.sources.size(), run.exact_references,
            run.exact_cached);
    appendf(out, "  %-18s %10s %10s %9s %9s %9s %8s %8s %9s %8s %8s %8s %8s %8s %8s %6s\n", "method", "precomp_s", "query_ms",
            "Mvert/s", "cyc/vert", "steps/tri", "MRE_%", "maxRE_%", "state_B/v", "heap_B/v", "x_dijk", "x_heat",
            "x_gsp", "<line_%", ">edge_%", "bad");
    for (const MethodRun& mr : run.methods) {
      if (!mr.ok()) {
        appendf(out, "  %-18s skipped (see the note below)\n", mr.method.name);
        continue;
      }
      const Summary s = summarise(run, mr);
      out += "  ";
      appendf(out, "%-18s", mr.method.name);
      out += " " + cell(s.precompute_s, 10, "%.4f") + " " + cell(s.query_s * 1e3, 10, "%.3f") + " " +
             cell(s.vertices_per_s * 1e-6, 9, "%.3f") + " " + cell(s.cycles_per_vertex, 9, "%.0f") + " " +
             cell(s.update_steps_per_triangle, 9, "%.3f") + " " + cell(s.mre * 100, 8, "%.4f") + " " +
             cell(s.max_re * 100, 8, "%.3f") + " " + cell(s.state_bytes_per_vertex, 9, "%.1f") + " " +
             cell(s.solver_bytes_per_vertex, 8, "%.0f") + " " + cell(s.vs_dijkstra, 8, "%.3f") + " " +
             cell(s.vs_heat, 8, "%.3f") + " " + cell(s.vs_gsp, 8, "%.3f") + " " + bound_cells(s) + "\n";
    }
    for (const std::string& note : run.notes) appendf(out, "  note: %s\n", note.c_str());
    out += "\n";
  }

  // The headline ratios: per mesh where both sides ran, then their geometric mean.
  struct Pair {
    const char* label;
    Method num, den;
    GeoMean mean;
  };
  Pair pairs[] = {{"gsp / dijkstra", Method::gsp, Method::dijkstra, {}},
                  {"gsp / heat solve", Method::gsp, Method::heat, {}},
                  {"gsp / heat-idt solve", Method::gsp, Method::heat_idt, {}},
                  {"random layout / gsp", Method::gsp_random_layout, Method::gsp, {}},
                  {"no layout / gsp", Method::gsp_no_layout, Method::gsp, {}}};
  out += points_section(report);
  bool any = false;
  for (const Pair& p : pairs)
    for (const MeshRun& run : report.runs)
      any = any || std::isfinite(time_of(run, p.num) / time_of(run, p.den));
  if (!any) return out;
  out += "query-time ratios (lower = the first is faster)\n";
  appendf(out, "  %-28s", "mesh");
  for (const Pair& p : pairs) appendf(out, " %21s", p.label);
  out += "\n";
  for (const MeshRun& run : report.runs) {
    appendf(out, "  %-28s", run.mesh->name.c_str());
    for (Pair& p : pairs) {
      const double r = time_of(run, p.num) / time_of(run, p.den);
      p.mean.add(r);
      out += " " + cell(r, 21, "%.3f");
    }
    out += "\n";
  }
  appendf(out, "  %-28s", "geometric mean");
  for (const Pair& p : pairs) out += " " + cell(p.mean.value(), 21, "%.3f");
  out += "\n";
  return out;
}

}  // namespace gsp::bench
