#include "report.hpp"

#include "format.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>

namespace gsp::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const MethodRun* find(const MeshRun& run, Method id) {
  for (const MethodRun& m : run.methods)
    if (m.method.id == id && m.ok()) return &m;
  return nullptr;
}

double query_seconds(const MethodRun& m) {
  std::vector<double> per_source;
  for (const SourceRun& s : m.sources)
    if (!s.seconds.empty()) per_source.push_back(median(s.seconds));
  return median(per_source);
}

double ratio_to(const MeshRun& run, Method other, double mine) {
  const MethodRun* o = find(run, other);
  if (!o) return kNaN;
  const double t = query_seconds(*o);
  return t > 0 ? mine / t : kNaN;
}

std::string hex(std::uint64_t h) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, h);
  return buf;
}

// The bound columns; empty where no distances were checked (a skipped method).
std::string bound_fields(const Summary& s) {
  if (!s.bound_sources) return ",,,,,";
  const BoundStats& b = s.bounds;
  return field(b.below_line) + "," + std::to_string(b.below_count) + "," + field(b.above_edge) + "," +
         std::to_string(b.above_count) + "," + std::to_string(b.unreached) + "," + std::to_string(b.nan);
}

}  // namespace

Summary summarise(const MeshRun& run, const MethodRun& m) {
  Summary s{};
  const double nv = double(run.mesh->mesh.num_vertices());
  const double nf = double(run.mesh->mesh.num_faces());
  s.precompute_s = m.ok() ? m.precompute_s : kNaN;
  s.query_s = query_seconds(m);
  std::vector<double> throughput, cycles;
  double steps = 0, mre = 0, max_re = 0, signed_re = 0;
  std::size_t stats_sources = 0;
  for (const SourceRun& r : m.sources) {
    if (!r.seconds.empty()) {
      ++s.timed_sources;
      const double t = median(r.seconds);
      if (t > 0 && r.reached) throughput.push_back(double(r.reached) / t);
    }
    if (!r.cycles.empty() && have_cycle_counter() && r.reached) cycles.push_back(median(r.cycles) / double(r.reached));
    if (r.has_stats && is_gsp(m.method.id)) {
      const double faces = r.stats.faces_reached ? double(r.stats.faces_reached) : nf;
      if (faces > 0) steps += double(r.stats.update_steps) / faces, ++stats_sources;
    }
    if (r.has_bounds) s.bounds = worst_of(s.bounds, r.bounds), ++s.bound_sources;
    if (r.has_errors) {
      mre += r.errors.mre, signed_re += r.errors.signed_re, max_re = std::max(max_re, r.errors.max_re), ++s.error_sources;
      s.unreached += r.errors.unreached;
    }
  }
  s.vertices_per_s = median(throughput);
  s.cycles_per_vertex = median(cycles);
  s.update_steps_per_triangle = stats_sources ? steps / double(stats_sources) : kNaN;
  s.mre = s.error_sources ? mre / double(s.error_sources) : kNaN;
  s.max_re = s.error_sources ? max_re : kNaN;
  s.signed_re = s.error_sources ? signed_re / double(s.error_sources) : kNaN;
  s.state_bytes_per_vertex = is_gsp(m.method.id) && m.ok() ? double(m.state_bytes) / nv : kNaN;
  s.solver_bytes_per_vertex = m.ok() && m.solver_bytes >= 0 ? m.solver_bytes / nv : kNaN;
  s.vs_dijkstra = ratio_to(run, Method::dijkstra, s.query_s);
  s.vs_heat = ratio_to(run, Method::heat, s.query_s);
  s.vs_heat_idt = ratio_to(run, Method::heat_idt, s.query_s);
  s.vs_gsp = ratio_to(run, Method::gsp, s.query_s);
  return s;
}

cli::Json bounds_json(const BoundStats& b) {
  cli::Json j;
  j["below_line"] = b.below_line;
  j["below_line_count"] = b.below_count;
  j["above_edge"] = b.above_edge;
  j["above_edge_count"] = b.above_count;
  j["edge_unreached"] = b.unreached;
  j["nan"] = b.nan;
  j["violated"] = violates(b);
  return j;
}

cli::Json to_json(const Report& report) {
  cli::Json doc;
  doc["settings"] = report.settings;
  doc["machine"] = report.machine;
  doc["total_work_items"] = report.total_items;
  cli::Json& items = doc["work_items"] = cli::Json::array();
  for (const WorkItem& w : report.items) {
    cli::Json item;
    item["index"] = w.index;
    item["mesh"] = report.all_meshes[w.mesh]->name;
    item["source"] = w.source;
    items.push_back(std::move(item));
  }
  cli::Json& meshes = doc["meshes"] = cli::Json::array();
  for (const MeshRun& run : report.runs) {
    cli::Json mj;
    mj["name"] = run.mesh->name;
    mj["path"] = run.mesh->path;
    mj["vertices"] = run.mesh->mesh.num_vertices();
    mj["faces"] = run.mesh->mesh.num_faces();
    mj["hash"] = hex(run.mesh->hash);
    mj["sources"] = cli::Json::array_of(run.sources);
    mj["exact_references"] = run.exact_references;
    mj["exact_cached"] = run.exact_cached;
    mj["notes"] = cli::Json::array_of(run.notes);
    cli::Json& methods = mj["methods"] = cli::Json::array();
    for (const MethodRun& m : run.methods) {
      const Summary s = summarise(run, m);
      cli::Json j;
      j["method"] = m.method.name;
      j["status"] = m.ok() ? "ok" : "skipped";
      if (!m.ok()) j["reason"] = m.skipped;
      j["precompute_s"] = number_or_null(s.precompute_s);
      j["query_s"] = number_or_null(s.query_s);
      j["vertices_per_s"] = number_or_null(s.vertices_per_s);
      j["cycles_per_vertex"] = number_or_null(s.cycles_per_vertex);
      j["update_steps_per_triangle"] = number_or_null(s.update_steps_per_triangle);
      j["mre"] = number_or_null(s.mre);
      j["max_re"] = number_or_null(s.max_re);
      j["signed_re"] = number_or_null(s.signed_re);
      j["unreached"] = s.unreached;
      j["state_bytes_per_vertex"] = number_or_null(s.state_bytes_per_vertex);
      j["solver_bytes_per_vertex"] = number_or_null(s.solver_bytes_per_vertex);
      j["vs_dijkstra"] = number_or_null(s.vs_dijkstra);
      j["vs_heat"] = number_or_null(s.vs_heat);
      j["vs_heat_idt"] = number_or_null(s.vs_heat_idt);
      j["vs_gsp"] = number_or_null(s.vs_gsp);
      j["bounds"] = s.bound_sources ? bounds_json(s.bounds) : cli::Json();
      if (is_gsp(m.method.id) && m.ok()) j["intrinsic_flips"] = m.intrinsic_flips;
      if ((m.method.id == Method::gsp_2threads || m.method.id == Method::gsp_4threads) && m.ok()) {
        // The parallel propagation against one thread: the speed-up, and the time beyond
        // perfect scaling per dual-queue round (thread start, messages, waiting), in us.
        const unsigned threads = m.method.id == Method::gsp_2threads ? 2 : 4;
        double rounds = 0;
        std::size_t n = 0;
        for (const SourceRun& r : m.sources)
          if (r.has_stats) rounds += double(r.stats.iterations), ++n;
        const double one = s.query_s / s.vs_gsp;   // gsp's query time
        j["threads"] = threads;
        j["speedup"] = number_or_null(1 / s.vs_gsp);
        j["overhead_per_round_us"] =
            number_or_null(n && rounds > 0 ? 1e6 * (s.query_s - one / threads) / (rounds / double(n)) : kNaN);
      }
      if (m.method.id == Method::points_gsp) {
        // The bar: point-cloud GSP's MRE against Dijkstra's on the same k-NN graph.
        const MethodRun* d = find(run, Method::points_dijkstra);
        j["points_dijkstra_mre_ratio"] = number_or_null(d ? summarise(run, *d).mre / s.mre : kNaN);
      }
      cli::Json& per = j["per_source"] = cli::Json::array();
      for (const SourceRun& r : m.sources) {
        cli::Json sj;
        sj["source"] = r.source;
        if (r.from_cache) sj["from_cache"] = true;
        sj["median_s"] = number_or_null(median(r.seconds));
        sj["seconds"] = cli::Json::array_of(r.seconds);
        sj["wall_seconds"] = cli::Json::array_of(r.wall_seconds);
        sj["cpu_seconds"] = cli::Json::array_of(r.cpu_seconds);
        sj["cycles"] = cli::Json::array_of(r.cycles);
        sj["reached"] = r.reached;
        if (r.has_stats) {
          sj["update_steps"] = r.stats.update_steps;
          sj["face_updates"] = r.stats.face_updates;
          sj["enqueued"] = r.stats.enqueued;
          sj["faces_reached"] = r.stats.faces_reached;
        }
        if (r.has_bounds) sj["bounds"] = bounds_json(r.bounds);
        if (r.has_errors) {
          sj["mre"] = r.errors.mre;
          sj["max_re"] = r.errors.max_re;
          sj["signed_re"] = r.errors.signed_re;
          sj["unreached"] = r.errors.unreached;
        }
        per.push_back(std::move(sj));
      }
      methods.push_back(std::move(j));
    }
    meshes.push_back(std::move(mj));
  }
  return doc;
}

std::string csv_header() {
  return "mesh,vertices,faces,method,status,sources,repetitions,precompute_s,query_s,vertices_per_s,"
         "cycles_per_vertex,update_steps_per_triangle,mre,max_re,unreached,state_bytes_per_vertex,"
         "solver_bytes_per_vertex,vs_dijkstra,vs_heat,vs_heat_idt,vs_gsp,exact_cached,clock,below_line,"
         "below_line_count,above_edge,above_edge_count,edge_unreached,nan_count\n";
}

std::string to_csv(const Report& report) {
  std::string out = csv_header();
  const std::string repetitions = std::to_string(report.repetitions);
  for (const MeshRun& run : report.runs)
    for (const MethodRun& m : run.methods) {
      const Summary s = summarise(run, m);
      const std::size_t cached = m.method.id == Method::exact ? run.exact_cached : 0;
      out += field(run.mesh->name) + "," + std::to_string(run.mesh->mesh.num_vertices()) + "," +
             std::to_string(run.mesh->mesh.num_faces()) + "," + m.method.name + "," +
             (m.ok() ? std::string("ok") : field("skipped: " + m.skipped)) + "," + std::to_string(run.sources.size()) +
             "," + (m.method.id == Method::exact ? "1" : repetitions) + "," + field(s.precompute_s) + "," +
             field(s.query_s) + "," + field(s.vertices_per_s) + "," + field(s.cycles_per_vertex) + "," +
             field(s.update_steps_per_triangle) + "," + field(s.mre) + "," + field(s.max_re) + "," +
             std::to_string(s.unreached) + "," + field(s.state_bytes_per_vertex) + "," +
             field(s.solver_bytes_per_vertex) + "," + field(s.vs_dijkstra) + "," + field(s.vs_heat) + "," +
             field(s.vs_heat_idt) + "," + field(s.vs_gsp) + "," + std::to_string(cached) + "," + report.clock + "," + bound_fields(s) + "\n";
    }
  return out;
}

}  // namespace gsp::bench
